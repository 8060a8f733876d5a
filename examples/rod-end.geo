// A rod end: an eye (outer radius 18, bore 9) joined by a shaft 10 wide and 150
// long to a clevis block (30 x 24) with a pin hole (radius 5). Genus 0 with 3
// boundaries (chi = -1). The shaft and the eye's ring are about 3.5 quads wide at
// 1.5% of the diagonal, too narrow for cones 2 quads from the boundary: the
// placement brings the rest of them nearer (cone_placement.h).
SetFactory("OpenCASCADE");
L = 150;
Disk(1) = {0, 0, 0, 18};
Rectangle(2) = {0, -5, 0, L, 10};
Rectangle(3) = {L - 10, -12, 0, 30, 24};
BooleanUnion(4) = { Surface{1}; Delete; }{ Surface{2, 3}; Delete; };
Disk(5) = {0, 0, 0, 9};
Disk(6) = {L + 5, 0, 0, 5};
BooleanDifference(7) = { Surface{4}; Delete; }{ Surface{5, 6}; Delete; };
Physical Curve("bore") = Curve In BoundingBox{-10, -10, -1, 10, 10, 1};
Physical Curve("pin_hole") = Curve In BoundingBox{L - 1, -6, -1, L + 11, 6, 1};
Physical Curve("outer") = Curve In BoundingBox{-19, -19, -1, L + 21, 19, 1};
Physical Curve("outer") -= {Curve In BoundingBox{-10, -10, -1, 10, 10, 1}, Curve In BoundingBox{L - 1, -6, -1, L + 11, 6, 1}};
Physical Surface("rod_end") = {7};
