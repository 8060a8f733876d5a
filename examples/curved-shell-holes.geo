// A curved shell with two holes: a 120-degree cylindrical panel (radius 50 mm,
// length 80 mm) pierced by two round holes, like a tank or fuselage panel.
//   quadmesh mesh examples/curved-shell-holes.geo -o shell.msh
// The output keeps the physical curves below for the solver's boundary conditions.
SetFactory("OpenCASCADE");
R = 50; L = 80;
Circle(1) = {0, 0, 0, R, -Pi/3, Pi/3};
Extrude {0, 0, L} { Curve{1}; }
Cylinder(10) = {0, 0, 25, 2 * R, 0, 0, 9};
Cylinder(11) = {0, 18, 55, 2 * R, 0, 0, 7};
BooleanDifference{ Surface{1}; Delete; }{ Volume{10, 11}; Delete; }
// curve numbers after the cut (Gmsh 4.8): 2, 3 the arcs at z = 0 and z = L,
// 1, 4 the straight sides, 6 + 7 the larger hole, 5 the smaller one
Physical Curve("end_z0") = {2};
Physical Curve("end_z80") = {3};
Physical Curve("side_y_plus") = {1};
Physical Curve("side_y_minus") = {4};
Physical Curve("hole_large") = {6, 7};
Physical Curve("hole_small") = {5};
