// A 100 x 60 plate with two circular holes of radius 10: the basic FEA case.
// Genus 0 with 3 boundaries (chi = -1). The physical curves name the boundaries;
// quadmesh puts the quads' boundary edges into these groups.
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 100, 60};
Disk(2) = {30, 30, 0, 10, 10};
Disk(3) = {70, 30, 0, 10, 10};
BooleanDifference{ Surface{1}; Delete; }{ Surface{2, 3}; Delete; }
Physical Curve("hole_left") = Curve In BoundingBox{19, 19, -1, 41, 41, 1};
Physical Curve("hole_right") = Curve In BoundingBox{59, 19, -1, 81, 41, 1};
Physical Curve("outer") = Curve In BoundingBox{-1, -1, -1, 101, 61, 1};
Physical Curve("outer") -= {Curve In BoundingBox{19, 19, -1, 41, 41, 1}, Curve In BoundingBox{59, 19, -1, 81, 41, 1}};
Physical Surface("plate") = {1};
