// A flanged neck (mid-surface, 3D): an annular flange of outer radius 60 with four
// bolt holes (radius 5 on a 45 circle), a fillet of radius 6 into a cylindrical neck
// of radius 25 and height 50. Genus 0 with 6 boundaries (chi = -4). Units mm.
SetFactory("OpenCASCADE");
Point(1) = {60, 0, 0}; Point(2) = {31, 0, 0}; Point(3) = {31, 0, 6}; Point(4) = {25, 0, 6};
Point(5) = {25, 0, 50};
Line(1) = {1, 2}; Circle(2) = {2, 3, 4}; Line(3) = {4, 5};
Extrude {{0, 0, 1}, {0, 0, 0}, 2 * Pi} { Curve{1, 2, 3}; }
wall() = Surface{:};
For i In {0:3}
  Cylinder(10 + i) = {45 * Cos(i * Pi / 2 + Pi / 4), 45 * Sin(i * Pi / 2 + Pi / 4), -5, 0, 0, 10, 5};
EndFor
BooleanDifference{ Surface{wall()}; Delete; }{ Volume{10:13}; Delete; }
