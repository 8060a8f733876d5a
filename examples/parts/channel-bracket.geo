// A channel bent from sheet (mid-surface, 3D): a base 80 wide and two walls 35
// high through bends of inner radius 4, 120 long; two holes (radius 8) in the base
// and one (radius 6) in each wall. Genus 0 with 5 boundaries (chi = -3). Units mm.
SetFactory("OpenCASCADE");
r = 4;
Point(1) = {0, 0, 35}; Point(2) = {0, 0, r}; Point(3) = {r, 0, r}; Point(4) = {r, 0, 0};
Point(5) = {80 - r, 0, 0}; Point(6) = {80 - r, 0, r}; Point(7) = {80, 0, r}; Point(8) = {80, 0, 35};
Line(1) = {1, 2}; Circle(2) = {2, 3, 4}; Line(3) = {4, 5}; Circle(4) = {5, 6, 7}; Line(5) = {7, 8};
Extrude {0, 120, 0} { Curve{1:5}; }
wall() = Surface{:};
Cylinder(10) = {40, 30, -5, 0, 0, 10, 8};
Cylinder(11) = {40, 90, -5, 0, 0, 10, 8};
Cylinder(12) = {-5, 60, 20, 10, 0, 0, 6};
Cylinder(13) = {75, 60, 20, 10, 0, 0, 6};
BooleanDifference{ Surface{wall()}; Delete; }{ Volume{10:13}; Delete; }
