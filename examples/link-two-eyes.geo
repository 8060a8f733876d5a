// A link (connecting rod blank): a big eye (outer radius 24, bore 14) and a small
// eye (outer radius 16, bore 8) joined by a shaft 12 wide whose length is 4 big-eye
// diameters (192 between the eye centres). Genus 0 with 3 boundaries (chi = -1).
// The shaft is bounded on both sides by one loop: a translation surface's quad
// size decays along it (issue 18).
SetFactory("OpenCASCADE");
L = 4 * 48;
Disk(1) = {0, 0, 0, 24};
Disk(2) = {L, 0, 0, 16};
Rectangle(3) = {0, -6, 0, L, 12};
BooleanUnion(4) = { Surface{1}; Delete; }{ Surface{2, 3}; Delete; };
Disk(5) = {0, 0, 0, 14};
Disk(6) = {L, 0, 0, 8};
BooleanDifference(7) = { Surface{4}; Delete; }{ Surface{5, 6}; Delete; };
Physical Curve("bore_big") = Curve In BoundingBox{-15, -15, -1, 15, 15, 1};
Physical Curve("bore_small") = Curve In BoundingBox{L - 9, -9, -1, L + 9, 9, 1};
Physical Curve("outer") = Curve In BoundingBox{-25, -25, -1, L + 17, 25, 1};
Physical Curve("outer") -= {Curve In BoundingBox{-15, -15, -1, 15, 15, 1}, Curve In BoundingBox{L - 9, -9, -1, L + 9, 9, 1}};
Physical Surface("link") = {7};
