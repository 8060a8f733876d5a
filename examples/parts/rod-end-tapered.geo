// A forged rod end / link with a tapered shank: a big eye (outer radius 32, bore 18)
// and a small eye (outer radius 15, bore 6.5) with centres 170 apart, the shank
// tapering from 36 wide at the big eye to 18 wide at the small one, plus a
// lightening hole (radius 6) in the shank. Planar, genus 0 with 4 boundaries (chi = -2).
// Units mm.
SetFactory("OpenCASCADE");
L = 170;
Disk(1) = {0, 0, 0, 32, 32};
Disk(2) = {L, 0, 0, 15, 15};
Point(101) = {0, -18, 0}; Point(102) = {L, -9, 0}; Point(103) = {L, 9, 0}; Point(104) = {0, 18, 0};
Line(101) = {101, 102}; Line(102) = {102, 103}; Line(103) = {103, 104}; Line(104) = {104, 101};
Curve Loop(101) = {101 : 104};
Plane Surface(3) = {101};
BooleanUnion(4) = { Surface{1}; Delete; }{ Surface{2, 3}; Delete; };
Disk(5) = {0, 0, 0, 18, 18};
Disk(6) = {L, 0, 0, 6.5, 6.5};
Disk(7) = {85, 0, 0, 6, 6};
BooleanDifference(8) = { Surface{4}; Delete; }{ Surface{5, 6, 7}; Delete; };
Physical Curve("bore_big") = Curve In BoundingBox{-19, -19, -1, 19, 19, 1};
Physical Curve("bore_small") = Curve In BoundingBox{L - 7.5, -7.5, -1, L + 7.5, 7.5, 1};
Physical Surface("rod_end") = {8};
