// A right-angle gusset plate, legs 120 (two 45-degree corners), with three holes
// (radius 8, 6 and 6). Its cones meet every criterion at the size band's edge (93%
// of the quads within [0.5, 2] x the size, the largest 3.0 x; docs/cones.md), every
// corner in one quad, where the Abel quads split each and have one 6.8 x the size.
// Planar, genus 0 with 4 boundaries (chi = -2).
// Units mm.
SetFactory("OpenCASCADE");
Point(1) = {0, 0, 0}; Point(2) = {120, 0, 0}; Point(3) = {0, 120, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};
Disk(2) = {25, 25, 0, 8}; Disk(3) = {70, 20, 0, 6}; Disk(4) = {20, 70, 0, 6};
BooleanDifference(5) = { Surface{1}; Delete; }{ Surface{2 : 4}; Delete; };
Physical Surface("gusset") = {5};
