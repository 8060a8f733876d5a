// A joggled sheet-metal bracket (mid-surface, 3D): two flanges 60 and 60 long,
// offset by 30 through two opposite bends of inner radius 5, 60 wide, a hole of
// radius 7 in each flange. Genus 0 with 3 boundaries (chi = -1). Units mm.
SetFactory("OpenCASCADE");
r = 5;
Point(1) = {-60, 0, 0}; Point(2) = {0, 0, 0}; Point(3) = {0, 0, r}; Point(4) = {r, 0, r};
Point(5) = {r, 0, 30 - r}; Point(6) = {2 * r, 0, 30 - r}; Point(7) = {2 * r, 0, 30}; Point(8) = {70, 0, 30};
Line(1) = {1, 2}; Circle(2) = {2, 3, 4}; Line(3) = {4, 5}; Circle(4) = {5, 6, 7}; Line(5) = {7, 8};
Extrude {0, 60, 0} { Curve{1:5}; }
wall() = Surface{:};
Cylinder(10) = {-30, 30, -5, 0, 0, 10, 7};
Cylinder(11) = {40, 30, 25, 0, 0, 10, 7};
BooleanDifference{ Surface{wall()}; Delete; }{ Volume{10, 11}; Delete; }
