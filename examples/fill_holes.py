"""Fill the holes of a mesh, repairing it first if fill refuses it; print the report, render before and after.

    PYTHONPATH=build/python /usr/bin/python3 examples/fill_holes.py data/hand_lowres.obj out/
"""

import pathlib
import sys

import fairsurf

source, out = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
out.mkdir(parents=True, exist_ok=True)
V, F = fairsurf.read_mesh(source)
try:
    V2, F2, report = fairsurf.fill_holes(V, F, continuity="G2")
except fairsurf.RepairableMeshError as refusal:
    print(f"refused: {refusal}")
    # As `fairsurf fill --repair`: the pinches of the border stay joined for the fill to close.
    V, F, repaired = fairsurf.repair(V, F, keep_border_pinches=True)
    print("repaired: " + ", ".join(f"{key} {value}" for key, value in repaired.items()
                                    if key.endswith(("removed", "merged", "split", "flipped")) and value))
    V2, F2, report = fairsurf.fill_holes(V, F, continuity="G2")
for hole in report["holes"]:
    print(f"hole {hole['index']}: {hole['status']}, {hole['delivered']}, +{hole['vertices_added']} vertices")
fairsurf.write_mesh(out / "filled.ply", V2, F2)
fairsurf.render(V, F, compare=[(V2, F2)], labels=["before", "after"],
                views=["iso", "bottom"], size=(800, 800), path=out / "fill.png")
print(f"wrote {out / 'filled.ply'} and {out / 'fill.png'}")
