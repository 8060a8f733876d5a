// A guide plate 150 x 100 with two adjustment slots (40 x 12, their corners
// rounded to radius 5) side by side and a round hole (radius 15) above them.
// Planar, genus 0 with 4 boundaries (chi = -2). Units mm.
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 150, 100};
Rectangle(2) = {20, 20, 0, 40, 12, 5};
Rectangle(3) = {90, 20, 0, 40, 12, 5};
Disk(4) = {75, 65, 0, 15, 15};
BooleanDifference(5) = { Surface{1}; Delete; }{ Surface{2 : 4}; Delete; };
Physical Surface("plate") = {5};
