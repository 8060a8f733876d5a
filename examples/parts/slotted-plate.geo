// An adjustment plate 160 x 90 with rounded corners (radius 8), an obround slot
// (60 long between centres, 16 wide) along its axis, and two round holes
// (radius 5) at the far end. Planar, genus 0 with 4 boundaries (chi = -2). Units mm.
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 160, 90, 8};
Rectangle(2) = {30, 37, 0, 60, 16};
Disk(3) = {30, 45, 0, 8, 8};
Disk(4) = {90, 45, 0, 8, 8};
BooleanUnion(5) = { Surface{2}; Delete; }{ Surface{3, 4}; Delete; };
Disk(6) = {135, 22, 0, 5, 5};
Disk(7) = {135, 68, 0, 5, 5};
BooleanDifference(8) = { Surface{1}; Delete; }{ Surface{5, 6, 7}; Delete; };
Physical Curve("slot") = Curve In BoundingBox{21, 36, -1, 99, 54, 1};
Physical Surface("plate") = {8};
