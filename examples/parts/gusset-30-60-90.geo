// A triangular gusset plate, legs 160 and 92.4 (corners of 30, 60 and 90 degrees),
// with three bolt holes (radius 7, 6 and 5). The 30- and 60-degree corners are in
// one quad each: the cone metric's scale vanishes at them like r^2 and r^0.5, and
// the sizes the cones are placed for and the map is fitted to leave that out near
// them (libquadmesh/cones/tip_scale.h). Planar, genus 0 with 4 boundaries
// (chi = -2). Units mm.
SetFactory("OpenCASCADE");
Point(1) = {0, 0, 0}; Point(2) = {160, 0, 0}; Point(3) = {0, 160 * Tan(Pi / 6), 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};
Disk(2) = {25, 25, 0, 7}; Disk(3) = {70, 15, 0, 6}; Disk(4) = {20, 60, 0, 5};
BooleanDifference(5) = { Surface{1}; Delete; }{ Surface{2 : 4}; Delete; };
Physical Surface("gusset") = {5};
