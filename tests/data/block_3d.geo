// A 1 x 1 x 1 block of 2 x 2 x 2 CUB8 beside a wedge column of PRI6,
// each an extrusion in z with 2 layers.
// Regenerate: gmsh -3 -format msh22 block_3d.geo -o block_3d_v22.msh
//             gmsh -3 -format msh41 block_3d.geo -o block_3d_v41.msh
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Point(5) = {2, 0, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {2, 5}; Line(6) = {5, 3};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, -2}; Plane Surface(2) = {2};
Transfinite Curve{1, 2, 3, 4, 5, 6} = 3;
Transfinite Surface{1}; Recombine Surface{1};
Transfinite Surface{2};
hex[] = Extrude {0, 0, 1} { Surface{1}; Layers{2}; Recombine; };
pri[] = Extrude {0, 0, 1} { Surface{2}; Layers{2}; Recombine; };
Physical Volume("HEXA") = {hex[1]};
Physical Volume("PRISM") = {pri[1]};
Physical Surface("BASE") = {1, 2};
