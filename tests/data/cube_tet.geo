// A unit cube of TET4 (unstructured; counts are read back from the file).
// Regenerate: gmsh -3 -format msh41 cube_tet.geo -o cube_tet_v41.msh
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
MeshSize{:} = 0.5;
Physical Volume("CUBE") = {1};
Physical Surface("BOTTOM") = {5};
