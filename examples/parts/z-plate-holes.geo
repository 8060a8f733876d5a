// A Z-shaped plate (a joggle link blank): a lower arm 100 x 30, a diagonal web and an
// upper arm 100 x 30 offset by 120 vertically, with two holes (radius 6) in each
// arm and an elongated lightening hole in the web. Planar, genus 0 with 6 boundaries
// (chi = -4). Units mm.
SetFactory("OpenCASCADE");
Point(1) = {0, 0, 0};    Point(2) = {100, 0, 0};  Point(3) = {100, 30, 0};
Point(4) = {70, 30, 0};  Point(5) = {160, 120, 0}; Point(6) = {220, 120, 0};
Point(7) = {220, 150, 0}; Point(8) = {120, 150, 0}; Point(9) = {120, 120, 0};
Point(10) = {30, 30, 0}; Point(11) = {0, 30, 0};
// the web is the band between lines 4-5 and 10-9 (offset 40 mm horizontally)
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 9};
Line(9) = {9, 10}; Line(10) = {10, 11}; Line(11) = {11, 1};
Curve Loop(1) = {1 : 11};
Plane Surface(1) = {1};
Disk(2) = {15, 15, 0, 6, 6};
Disk(3) = {85, 15, 0, 6, 6};
Disk(4) = {135, 135, 0, 6, 6};
Disk(5) = {205, 135, 0, 6, 6};
Disk(6) = {95, 75, 0, 14, 5};
Rotate {{0, 0, 1}, {95, 75, 0}, Pi / 4} { Surface{6}; }
BooleanDifference(7) = { Surface{1}; Delete; }{ Surface{2 : 6}; Delete; };
Physical Surface("z_plate") = {7};
