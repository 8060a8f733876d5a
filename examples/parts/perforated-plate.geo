// A perforated plate 200 x 120 with a 5 x 3 pattern of holes (radius 6, pitch 35).
// Fifteen holes and four right corners leave 60 valence-5 cones to the interior,
// far more than issue 18's bound (24): every hole is made a square on the lattice,
// and no interior cone is left. Planar, genus 0 with 16 boundaries (chi = -14).
// Units mm.
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 200, 120};
k = 2;
For i In {0:4}
  For j In {0:2}
    Disk(k) = {30 + 35 * i, 25 + 35 * j, 0, 6, 6};
    k = k + 1;
  EndFor
EndFor
BooleanDifference(100) = { Surface{1}; Delete; }{ Surface{2 : k - 1}; Delete; };
Physical Surface("perforated_plate") = {100};
