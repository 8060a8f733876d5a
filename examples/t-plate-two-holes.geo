// A T-plate: a flange 120 x 30 on a web 30 wide and 70 long, with a bolt hole at
// each end of the flange (radius 6). Genus 0 with 3 boundaries (chi = -1). Two
// concave 270-degree corners where the web meets the flange (three quads each)
// and six convex right corners (one quad each).
SetFactory("OpenCASCADE");
Point(1) = {45, 0, 0}; Point(2) = {75, 0, 0}; Point(3) = {75, 70, 0}; Point(4) = {120, 70, 0};
Point(5) = {120, 100, 0}; Point(6) = {0, 100, 0}; Point(7) = {0, 70, 0}; Point(8) = {45, 70, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6, 7, 8};
Plane Surface(1) = {1};
Disk(10) = {15, 85, 0, 6};
Disk(11) = {105, 85, 0, 6};
BooleanDifference{ Surface{1}; Delete; }{ Surface{10, 11}; Delete; }
Physical Curve("hole_left") = Curve In BoundingBox{8, 78, -1, 22, 92, 1};
Physical Curve("hole_right") = Curve In BoundingBox{98, 78, -1, 112, 92, 1};
Physical Curve("outer") = Curve In BoundingBox{-1, -1, -1, 121, 101, 1};
Physical Curve("outer") -= {Curve In BoundingBox{8, 78, -1, 22, 92, 1}, Curve In BoundingBox{98, 78, -1, 112, 92, 1}};
Physical Surface("plate") = {1};
