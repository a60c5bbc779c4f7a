// Same plate, second order triangles (TRI6) and 3-node lines (SEG3).
// Regenerate: gmsh -2 -format msh22 plate_tri6.geo -o plate_tri6_v22.msh
//             gmsh -2 -format msh41 plate_tri6.geo -o plate_tri6_v41.msh
Point(1) = {0, 0, 0}; Point(2) = {2, 0, 0}; Point(3) = {2, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 3; Transfinite Curve{2, 4} = 2;
Transfinite Surface{1};
Mesh.ElementOrder = 2;
Physical Surface("PLATE") = {1};
Physical Curve("BOTTOM") = {1};
