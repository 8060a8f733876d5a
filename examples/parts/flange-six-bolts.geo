// A circular pipe flange: outer radius 80, central bore radius 30, and six bolt
// holes of radius 7 on a pitch circle of radius 57.5. Planar, genus 0 with
// 8 boundaries (chi = -6). Units mm.
SetFactory("OpenCASCADE");
Ro = 80; Ri = 30; Rp = 57.5; Rb = 7;
Disk(1) = {0, 0, 0, Ro, Ro};
Disk(2) = {0, 0, 0, Ri, Ri};
For i In {0 : 5}
  Disk(10 + i) = {Rp * Cos(i * Pi / 3 + Pi / 6), Rp * Sin(i * Pi / 3 + Pi / 6), 0, Rb, Rb};
EndFor
BooleanDifference(20) = { Surface{1}; Delete; }{ Surface{2, 10 : 15}; Delete; };
Physical Curve("bore") = Curve In BoundingBox{-Ri - 1, -Ri - 1, -1, Ri + 1, Ri + 1, 1};
Physical Surface("flange") = {20};
