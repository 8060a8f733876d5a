// A right-triangular plate, legs 150 and 100 (corners of 33.7, 56.3 and 90
// degrees), with two holes (radius 8 and 6). The acute corners are in one quad
// each (see gusset-30-60-90.geo). Planar, genus 0 with 3 boundaries (chi = -1).
// Units mm.
SetFactory("OpenCASCADE");
Point(1) = {0, 0, 0}; Point(2) = {150, 0, 0}; Point(3) = {0, 100, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};
Disk(2) = {30, 30, 0, 8}; Disk(3) = {80, 20, 0, 6};
BooleanDifference(4) = { Surface{1}; Delete; }{ Surface{2, 3}; Delete; };
Physical Surface("plate") = {4};
