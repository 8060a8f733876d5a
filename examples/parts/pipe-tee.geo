// A pipe tee's wall (mid-surface, 3D): a run of radius 20 and length 160 and a
// branch of radius 15 rising 60 from its axis, meeting at a sharp crease (no
// fillet). Genus 0 with 3 boundaries (the three open ends; chi = -1). Units mm.
SetFactory("OpenCASCADE");
Cylinder(1) = {-80, 0, 0, 160, 0, 0, 20};
Cylinder(2) = {0, 0, 0, 0, 0, 60, 15};
BooleanUnion(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
ends() = Surface In BoundingBox{-81, -21, -21, -79, 21, 21};
ends() += Surface In BoundingBox{79, -21, -21, 81, 21, 21};
ends() += Surface In BoundingBox{-16, -16, 59, 16, 16, 61};
Delete { Volume{3}; }
Delete { Surface{ends()}; }
