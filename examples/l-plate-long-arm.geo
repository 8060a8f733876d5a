// An L-plate whose arm is 5 widths long (arm 20 wide, 100 long beyond the heel)
// with a bolt hole near the arm's end: a lever or a hanger. Genus 0 with 2
// boundaries (chi = 0). The long arm is where a translation surface's quad size
// decays (issue 18): the quarter-turn cones keep it in the band.
SetFactory("OpenCASCADE");
W = 20;  // arm width
Point(1) = {0, 0, 0}; Point(2) = {40, 0, 0}; Point(3) = {40, W, 0};
Point(4) = {W, W, 0}; Point(5) = {W, W + 5 * W, 0}; Point(6) = {0, W + 5 * W, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 6}; Line(6) = {6, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
Disk(10) = {W / 2, W + 5 * W - 12, 0, 4};
BooleanDifference{ Surface{1}; Delete; }{ Surface{10}; Delete; }
Physical Curve("hole") = Curve In BoundingBox{W / 2 - 5, W + 5 * W - 17, -1, W / 2 + 5, W + 5 * W - 7, 1};
Physical Curve("outer") = Curve In BoundingBox{-1, -1, -1, 41, W + 5 * W + 1, 1};
Physical Curve("outer") -= {Curve In BoundingBox{W / 2 - 5, W + 5 * W - 17, -1, W / 2 + 5, W + 5 * W - 7, 1}};
Physical Surface("plate") = {1};
