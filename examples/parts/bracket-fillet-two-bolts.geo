// An L-shaped mounting bracket plate: a horizontal arm 140 x 35 and a vertical arm
// 35 x 110 with an inner fillet of radius 15 at the re-entrant corner, a rounded
// outer corner (radius 10) and rounded arm ends, and two bolt holes (radius 6.5).
// Planar, genus 0 with 3 boundaries (chi = -1). Units mm.
SetFactory("OpenCASCADE");
T = 35; A = 140; B = 110; Rf = 15; Rb = 6.5;
Rectangle(1) = {0, 0, 0, A - T / 2, T};
Rectangle(2) = {0, 0, 0, T, B - T / 2};
Disk(3) = {A - T / 2, T / 2, 0, T / 2, T / 2};           // rounded end of the horizontal arm
Disk(4) = {T / 2, B - T / 2, 0, T / 2, T / 2};           // rounded end of the vertical arm
Rectangle(5) = {T, T, 0, Rf, Rf};                         // fillet block at the inner corner
Disk(6) = {T + Rf, T + Rf, 0, Rf, Rf};
BooleanDifference(7) = { Surface{5}; Delete; }{ Surface{6}; Delete; };
BooleanUnion(8) = { Surface{1}; Delete; }{ Surface{2, 3, 4, 7}; Delete; };
// round the outer corner at the origin: cut the corner square, add a quarter disk
Rectangle(9) = {0, 0, 0, 10, 10};
BooleanDifference(10) = { Surface{8}; Delete; }{ Surface{9}; Delete; };
Disk(11) = {10, 10, 0, 10, 10};
Rectangle(12) = {0, 0, 0, 10, 10};
BooleanIntersection(13) = { Surface{11}; Delete; }{ Surface{12}; Delete; };
BooleanUnion(14) = { Surface{10}; Delete; }{ Surface{13}; Delete; };
Disk(15) = {A - T / 2, T / 2, 0, Rb, Rb};
Disk(16) = {T / 2, B - T / 2, 0, Rb, Rb};
BooleanDifference(17) = { Surface{14}; Delete; }{ Surface{15, 16}; Delete; };
Physical Curve("bolt_a") = Curve In BoundingBox{A - T / 2 - Rb - 1, T / 2 - Rb - 1, -1, A - T / 2 + Rb + 1, T / 2 + Rb + 1, 1};
Physical Curve("bolt_b") = Curve In BoundingBox{T / 2 - Rb - 1, B - T / 2 - Rb - 1, -1, T / 2 + Rb + 1, B - T / 2 + Rb + 1, 1};
Physical Surface("bracket") = Surface{:};
