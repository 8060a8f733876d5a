// A square mounting flange 100 x 100 with rounded corners (radius 8), a central
// bore (radius 25) and four bolt holes (radius 5) on the diagonals, 36 from the
// centre. Planar, genus 0 with 6 boundaries (chi = -4). Units mm.
SetFactory("OpenCASCADE");
Rectangle(1) = {-50, -50, 0, 100, 100, 8};
Disk(2) = {0, 0, 0, 25, 25};
For i In {0 : 3}
  Disk(3 + i) = {36 * Cos(i * Pi / 2 + Pi / 4), 36 * Sin(i * Pi / 2 + Pi / 4), 0, 5, 5};
EndFor
BooleanDifference(10) = { Surface{1}; Delete; }{ Surface{2 : 6}; Delete; };
Physical Surface("flange") = {10};
