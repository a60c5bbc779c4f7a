// 2 x 1 plate, 4 x 2 QUA4 (transfinite), with named physical groups.
// Regenerate: gmsh -2 -format msh22 plate_quad4.geo -o plate_quad4_v22.msh
//             gmsh -2 -format msh41 plate_quad4.geo -o plate_quad4_v41.msh
Point(1) = {0, 0, 0}; Point(2) = {2, 0, 0}; Point(3) = {2, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 5; Transfinite Curve{2, 4} = 3;
Transfinite Surface{1}; Recombine Surface{1};
Physical Surface("PLATE") = {1};
Physical Curve("BOTTOM") = {1};
Physical Curve("LEFT") = {4};
Physical Point("CORNER") = {3};
