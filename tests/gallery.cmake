# Keeps docs/gallery.md honest: runs scripts/gallery.sh --check (the gallery's code path on small
# meshes and 360x150 images, about 30 s) with this build's CLI. The script itself fails unless every
# expected PNG is written and non-empty and every number it measured is finite. The full gallery
# (about 1.5 minutes) is not run here; regenerate it with scripts/gallery.sh.
find_program(FAIRSURF_BASH bash)
find_program(FAIRSURF_PYTHON3 python3)
if(FAIRSURF_BASH AND FAIRSURF_PYTHON3)
  add_test(NAME gallery_check
    COMMAND ${CMAKE_COMMAND} -E env FAIRSURF=$<TARGET_FILE:fairsurf_cli>
      ${FAIRSURF_BASH} ${PROJECT_SOURCE_DIR}/scripts/gallery.sh --check
      --out ${CMAKE_CURRENT_BINARY_DIR}/gallery_check)
  set_tests_properties(gallery_check PROPERTIES TIMEOUT 300)
else()
  message(STATUS "fairsurf: bash or python3 not found; the gallery_check test is not registered")
endif()
