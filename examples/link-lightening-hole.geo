// A connecting rod with a lightening hole: the link of link-two-eyes.geo (a big
// eye with a bore of radius 14, a small one with a bore of radius 8, a shaft 12
// wide and 192 between the eye centres) with a hole of radius 2.5 half-way along
// its shaft. Genus 0 with 4 boundaries (chi = -2). At 1.5% of the diagonal the
// shaft is 3.4 quads wide and the hole 1.4 across: no interior cone fits beside
// it, so the cone route puts valence-5 cones on its boundary (cone_route.h
// boundary_cone_placement).
SetFactory("OpenCASCADE");
L = 4 * 48;
Disk(1) = {0, 0, 0, 24};
Disk(2) = {L, 0, 0, 16};
Rectangle(3) = {0, -6, 0, L, 12};
BooleanUnion(4) = { Surface{1}; Delete; }{ Surface{2, 3}; Delete; };
Disk(5) = {0, 0, 0, 14};
Disk(6) = {L, 0, 0, 8};
Disk(8) = {L / 2, 0, 0, 2.5};
BooleanDifference(7) = { Surface{4}; Delete; }{ Surface{5, 6, 8}; Delete; };
Physical Curve("bore_big") = Curve In BoundingBox{-15, -15, -1, 15, 15, 1};
Physical Curve("bore_small") = Curve In BoundingBox{L - 9, -9, -1, L + 9, 9, 1};
Physical Curve("lightening_hole") = Curve In BoundingBox{L / 2 - 3, -3, -1, L / 2 + 3, 3, 1};
Physical Curve("outer") = Curve In BoundingBox{-25, -25, -1, L + 17, 25, 1};
Physical Curve("outer") -= {Curve In BoundingBox{-15, -15, -1, 15, 15, 1}, Curve In BoundingBox{L - 9, -9, -1, L + 9, 9, 1}, Curve In BoundingBox{L / 2 - 3, -3, -1, L / 2 + 3, 3, 1}};
Physical Surface("link") = {7};
