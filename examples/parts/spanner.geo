// A double-ended spanner blank, 244 long overall: an open-jaw head (outer radius 24, jaw
// 19 across flats, opening at 15 degrees to the handle) at one end and a ring head
// (outer radius 20) with a hexagonal hole (17 across flats) at the
// other, joined by a 16-wide handle with a lightening slot. Planar, genus 0 with
// 3 boundaries (chi = -1). Units mm.
SetFactory("OpenCASCADE");
L = 200;
Disk(1) = {0, 0, 0, 24, 24};
Disk(2) = {L, 0, 0, 20, 20};
Rectangle(3) = {0, -8, 0, L, 16};
BooleanUnion(4) = { Surface{1}; Delete; }{ Surface{2, 3}; Delete; };
// jaw: a slot 19 wide open to the left, ending in a half disk, rotated by 15 degrees
Rectangle(5) = {-40, -9.5, 0, 40, 19};
Disk(6) = {0, 0, 0, 9.5, 9.5};
BooleanUnion(7) = { Surface{5}; Delete; }{ Surface{6}; Delete; };
Rotate {{0, 0, 1}, {0, 0, 0}, Pi / 12} { Surface{7}; }
// hexagonal hole in the ring, 17 across flats
r = 8.5 / Cos(Pi / 6);
For i In {0 : 5}
  Point(100 + i) = {L + r * Cos(i * Pi / 3), r * Sin(i * Pi / 3), 0};
EndFor
For i In {0 : 5}
  Line(100 + i) = {100 + i, 100 + (i + 1) % 6};
EndFor
Curve Loop(100) = {100 : 105};
Plane Surface(8) = {100};
// lightening slot in the handle
Rectangle(9) = {60, -3, 0, 80, 6, 2.9};
BooleanDifference(10) = { Surface{4}; Delete; }{ Surface{7, 8, 9}; Delete; };
Physical Surface("spanner") = {10};
