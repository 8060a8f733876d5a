// A 160 x 100 plate with R12 corner fillets, an elliptical cut-out (60 x 30)
// and two bolt holes (radius 7). Its Abel quads have 96% in the size band, but
// the fillets leave one quad 3.7 x the size: the cone route meshes it. Planar,
// genus 0 with 4 boundaries (chi = -2). Units mm.
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 160, 100, 12};
Disk(2) = {80, 50, 0, 30, 15};
Disk(3) = {25, 25, 0, 7};
Disk(4) = {135, 75, 0, 7};
BooleanDifference(5) = { Surface{1}; Delete; }{ Surface{2, 3, 4}; Delete; };
Physical Surface("plate") = {5};
