// A triangular gusset plate (legs 180 and 140 along the x and y axes) with its three
// corners chamfered (15 mm at the right angle, 20 mm at the acute corners) and three
// bolt holes (radius 7) plus a lightening hole (radius 16) near the centroid.
// Planar, genus 0 with 5 boundaries (chi = -3). Units mm.
SetFactory("OpenCASCADE");
A = 180; B = 140; c0 = 15; c1 = 20;
// unit vector along the hypotenuse from (A,0) to (0,B)
Lh = Sqrt(A * A + B * B); ux = -A / Lh; uy = B / Lh;
Point(1) = {c0, 0, 0};
Point(2) = {A - c1, 0, 0};
Point(3) = {A + c1 * ux, c1 * uy, 0};
Point(4) = {-c1 * ux, B - c1 * uy, 0};
Point(5) = {0, B - c1, 0};
Point(6) = {0, c0, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};
Line(4) = {4, 5}; Line(5) = {5, 6}; Line(6) = {6, 1};
Curve Loop(1) = {1 : 6};
Plane Surface(1) = {1};
Disk(2) = {28, 28, 0, 7, 7};
Disk(3) = {A - 48, 18, 0, 7, 7};
Disk(4) = {18, B - 42, 0, 7, 7};
Disk(5) = {A / 3 + 4, B / 3 + 4, 0, 16, 16};
BooleanDifference(6) = { Surface{1}; Delete; }{ Surface{2 : 5}; Delete; };
Physical Surface("gusset") = {6};
