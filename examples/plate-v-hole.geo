// A 100 x 60 plate with a round hole and a triangular one whose sharpest corner,
// at (50, 30), is 16.3 degrees: the plate turns 343.7 degrees round that tip.
// Genus 0 with 3 boundaries (chi = -1). With h not vanishing there, two quads
// would share the 343.7 degrees; --form auto puts a zero of h at the tip
// (--tip-angle, README step 2), and four quads share it.
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 100, 60};
Disk(2) = {70, 30, 0, 10};
Point(100) = {15, 25, 0}; Point(101) = {50, 30, 0}; Point(102) = {15, 35, 0};
Line(100) = {100, 101}; Line(101) = {101, 102}; Line(102) = {102, 100};
Curve Loop(100) = {100, 101, 102}; Plane Surface(100) = {100};
BooleanDifference{ Surface{1}; Delete; }{ Surface{2, 100}; Delete; }
Physical Curve("hole_v") = Curve In BoundingBox{14, 24, -1, 51, 36, 1};
Physical Curve("hole_round") = Curve In BoundingBox{59, 19, -1, 81, 41, 1};
Physical Curve("outer") = Curve In BoundingBox{-1, -1, -1, 101, 61, 1};
Physical Curve("outer") -= {Curve In BoundingBox{14, 24, -1, 51, 36, 1}, Curve In BoundingBox{59, 19, -1, 81, 41, 1}};
Physical Surface("plate") = {1};
