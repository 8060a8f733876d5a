// A hexagonal flange: 120 across flats, a bore of radius 20 and six bolt holes of
// radius 5 on a 42 pitch radius, facing the flats. Its six 120-degree corners ask
// for one quad each, and with its seven holes they leave 30 valence-5 cones to the
// interior, more than issue 18's bound (24): the bolt holes are made squares on
// the lattice. Planar, genus 0 with 8 boundaries (chi = -6). Units mm.
SetFactory("OpenCASCADE");
R = 120 / Sqrt(3);  // circumradius
For i In {0:5}
  Point(i + 1) = {R * Cos(i * Pi / 3), R * Sin(i * Pi / 3), 0};
EndFor
For i In {0:5}
  Line(i + 1) = {i + 1, (i + 1) % 6 + 1};
EndFor
Curve Loop(1) = {1:6};
Plane Surface(1) = {1};
Disk(2) = {0, 0, 0, 20, 20};
For i In {0:5}
  Disk(3 + i) = {42 * Cos(i * Pi / 3 + Pi / 6), 42 * Sin(i * Pi / 3 + Pi / 6), 0, 5, 5};
EndFor
BooleanDifference(10) = { Surface{1}; Delete; }{ Surface{2 : 8}; Delete; };
Physical Surface("hex_flange") = {10};
