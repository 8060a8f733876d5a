// The FEA example's part: a 200 x 80 plate with two holes of radius 15, pulled
// along x (examples/fea/run). Plane stress in the z = 0 plane; the physical
// curves name the sides and the holes, which quadmesh writes as node sets and
// element-edge surfaces of its decks.
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 200, 80};
Disk(2) = {65, 40, 0, 15, 15};
Disk(3) = {135, 40, 0, 15, 15};
BooleanDifference{ Surface{1}; Delete; }{ Surface{2, 3}; Delete; }
Physical Curve("left") = Curve In BoundingBox{-1, -1, -1, 1, 81, 1};
Physical Curve("right") = Curve In BoundingBox{199, -1, -1, 201, 81, 1};
Physical Curve("bottom") = Curve In BoundingBox{-1, -1, -1, 201, 1, 1};
Physical Curve("top") = Curve In BoundingBox{-1, 79, -1, 201, 81, 1};
Physical Curve("holes") = Curve In BoundingBox{49, 24, -1, 151, 56, 1};
Physical Surface("plate") = {1};
