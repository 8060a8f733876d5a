// An assembly of five sheet parts side by side, for `quadmesh mesh
// --each-component --skip-unsupported`: four the method takes (a plate with two
// holes, a washer, a bracket with three holes, a strip with one slot) and a
// plain disk (a blank: chi = 1, no holomorphic 1-form), which is reported as
// unsupported and left out. Each part is a physical surface named after it.
SetFactory("OpenCASCADE");
// plate with two holes: genus 0, 3 boundaries, chi = -1
Rectangle(1) = {0, 0, 0, 40, 24};
Disk(2) = {12, 12, 0, 4, 4};
Disk(3) = {28, 12, 0, 4, 4};
BooleanDifference(10) = { Surface{1}; Delete; }{ Surface{2, 3}; Delete; };
// washer: an annulus, chi = 0
Disk(4) = {60, 12, 0, 12, 12};
Disk(5) = {60, 12, 0, 5, 5};
BooleanDifference(11) = { Surface{4}; Delete; }{ Surface{5}; Delete; };
// bracket with three holes: genus 0, 4 boundaries, chi = -2
Rectangle(6) = {0, 40, 0, 50, 20};
Disk(7) = {10, 50, 0, 3, 3};
Disk(8) = {25, 50, 0, 3, 3};
Disk(9) = {40, 50, 0, 3, 3};
BooleanDifference(12) = { Surface{6}; Delete; }{ Surface{7, 8, 9}; Delete; };
// strip with a slot: an annulus with corners, chi = 0
Rectangle(13) = {60, 40, 0, 30, 20};
Rectangle(14) = {68, 47, 0, 14, 6};
BooleanDifference(15) = { Surface{13}; Delete; }{ Surface{14}; Delete; };
// blank: a disk, unsupported
Disk(16) = {100, 12, 0, 8, 8};
Physical Surface("plate_two_holes") = {10};
Physical Surface("washer") = {11};
Physical Surface("bracket_three_holes") = {12};
Physical Surface("slotted_strip") = {15};
Physical Surface("blank_disk") = {16};
