// A bent sheet-metal bracket: two flanges (60 and 50 long, 50 wide) at a right
// angle joined by a bend of inner radius 6, each flange with a bolt hole (radius 5).
// A surface in 3D (the sheet's mid-surface). Genus 0 with 3 boundaries (chi = -1).
// The bend is where the stresses are; its quads should stay at the requested size.
SetFactory("OpenCASCADE");
R = 6; A = 60; B = 50; D = 50;
// the profile in the x-y plane: flange along x, the bend, flange along y
Point(1) = {A, 0, 0}; Point(2) = {0, 0, 0}; Point(3) = {0, R, 0}; Point(4) = {-R, R, 0};
Point(5) = {-R, R + B, 0};
Line(1) = {1, 2};
Circle(2) = {2, 3, 4};
Line(3) = {4, 5};
Extrude {0, 0, D} { Curve{1, 2, 3}; }
Cylinder(10) = {A / 2, -5, D / 2, 0, 10, 0, 5};
Cylinder(11) = {-R - 5, R + B / 2 + 5, D / 2, 10, 0, 0, 5};
BooleanDifference{ Surface{1, 2, 3}; Delete; }{ Volume{10, 11}; Delete; }
Physical Curve("hole_base") = Curve In BoundingBox{A / 2 - 6, -1, D / 2 - 6, A / 2 + 6, 1, D / 2 + 6};
Physical Curve("hole_upright") = Curve In BoundingBox{-R - 1, R + B / 2 - 1, D / 2 - 6, -R + 1, R + B / 2 + 11, D / 2 + 6};
Physical Surface("bracket") = Surface{:};
