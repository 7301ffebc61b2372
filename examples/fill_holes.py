"""Fill the hole of a mesh, print the report, render before and after.

    PYTHONPATH=build/python /usr/bin/python3 examples/fill_holes.py data/hand_lowres.obj out/
"""

import pathlib
import sys

import fairsurf

source, out = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
out.mkdir(parents=True, exist_ok=True)
V, F = fairsurf.read_mesh(source)
V2, F2, report = fairsurf.fill_holes(V, F, continuity="G2")
for hole in report["holes"]:
    print(f"hole {hole['index']}: {hole['status']}, {hole['delivered']}, +{hole['vertices_added']} vertices")
fairsurf.write_mesh(out / "filled.ply", V2, F2)
fairsurf.render(V, F, compare=[(V2, F2)], labels=["before", "after"],
                views=["iso", "bottom"], size=(800, 800), path=out / "fill.png")
print(f"wrote {out / 'filled.ply'} and {out / 'fill.png'}")
