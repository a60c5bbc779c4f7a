// Same plate, 8-node quadrangles (QUA8) and SEG3 edges.
// Regenerate: gmsh -2 -format msh41 plate_quad8.geo -o plate_quad8_v41.msh
Point(1) = {0, 0, 0}; Point(2) = {2, 0, 0}; Point(3) = {2, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 3; Transfinite Curve{2, 4} = 2;
Transfinite Surface{1}; Recombine Surface{1};
Mesh.ElementOrder = 2; Mesh.SecondOrderIncomplete = 1;
Physical Surface("PLATE") = {1};
Physical Curve("TOP") = {3};
