// A concentric annulus, radii 1 and 2: chi = 0, the singularity-free case whose
// symmetric differential is known exactly (proportional to -i dz/z).
SetFactory("OpenCASCADE");
Disk(1) = {0, 0, 0, 2, 2};
Disk(2) = {0, 0, 0, 1, 1};
BooleanDifference{ Surface{1}; Delete; }{ Surface{2}; Delete; }
Physical Curve("outer") = Curve In BoundingBox{-2.1, -2.1, -1, 2.1, 2.1, 1};
Physical Curve("inner") = Curve In BoundingBox{-1.1, -1.1, -1, 1.1, 1.1, 1};
Physical Curve("outer") -= Curve In BoundingBox{-1.1, -1.1, -1, 1.1, 1.1, 1};
Physical Surface("annulus") = {1};
