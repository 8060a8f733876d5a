// An L-shaped plate (100 x 100, arms 40 wide) with three bolt holes: a bracket
// blank. Genus 0 with 4 boundaries (chi = -2). The physical curves name the
// boundaries; quadmesh puts the quads' boundary edges into these groups.
SetFactory("OpenCASCADE");
Point(1) = {0, 0, 0}; Point(2) = {100, 0, 0}; Point(3) = {100, 40, 0};
Point(4) = {40, 40, 0}; Point(5) = {40, 100, 0}; Point(6) = {0, 100, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 6}; Line(6) = {6, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
Disk(10) = {20, 20, 0, 8};
Disk(11) = {70, 20, 0, 6};
Disk(12) = {20, 75, 0, 7};
BooleanDifference{ Surface{1}; Delete; }{ Surface{10, 11, 12}; Delete; }
Physical Curve("hole_corner") = Curve In BoundingBox{11, 11, -1, 29, 29, 1};
Physical Curve("hole_foot") = Curve In BoundingBox{63, 13, -1, 77, 27, 1};
Physical Curve("hole_arm") = Curve In BoundingBox{12, 67, -1, 28, 83, 1};
Physical Curve("outer") = Curve In BoundingBox{-1, -1, -1, 101, 101, 1};
Physical Curve("outer") -= {Curve In BoundingBox{11, 11, -1, 29, 29, 1}, Curve In BoundingBox{63, 13, -1, 77, 27, 1}, Curve In BoundingBox{12, 67, -1, 28, 83, 1}};
Physical Surface("plate") = {1};
