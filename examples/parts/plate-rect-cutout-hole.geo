// A cover plate 220 x 140 with a rectangular cutout 70 x 45 (corner radius 5) for a
// connector, a round hole of radius 18 for a shaft, and four corner mounting
// holes (radius 4). Planar, genus 0 with 7 boundaries (chi = -5). Units mm.
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 220, 140};
Rectangle(2) = {30, 50, 0, 70, 45, 5};
Disk(3) = {160, 70, 0, 18, 18};
Disk(4) = {12, 12, 0, 4, 4};
Disk(5) = {208, 12, 0, 4, 4};
Disk(6) = {208, 128, 0, 4, 4};
Disk(7) = {12, 128, 0, 4, 4};
BooleanDifference(8) = { Surface{1}; Delete; }{ Surface{2 : 7}; Delete; };
Physical Curve("cutout") = Curve In BoundingBox{29, 49, -1, 101, 96, 1};
Physical Curve("shaft") = Curve In BoundingBox{141, 51, -1, 179, 89, 1};
Physical Surface("cover") = {8};
