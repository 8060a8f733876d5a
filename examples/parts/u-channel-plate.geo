// A U-shaped plate (the outline of a U-channel clevis blank): overall 160 wide and
// 130 tall, legs 40 wide, base 45 deep, inner corners filleted (radius 10), with a
// bolt hole (radius 8) near each leg tip and two holes (radius 6) in the base.
// Planar, genus 0 with 5 boundaries (chi = -3). Units mm.
SetFactory("OpenCASCADE");
W = 160; H = 130; Tl = 40; Tb = 45; Rf = 10;
Rectangle(1) = {0, 0, 0, W, H};
Rectangle(2) = {Tl, Tb, 0, W - 2 * Tl, H - Tb + 1, Rf};   // the slot between the legs, rounded corners
BooleanDifference(3) = { Surface{1}; Delete; }{ Surface{2}; Delete; };
Disk(4) = {Tl / 2, H - 22, 0, 8, 8};
Disk(5) = {W - Tl / 2, H - 22, 0, 8, 8};
Disk(6) = {W / 2 - 30, Tb / 2, 0, 6, 6};
Disk(7) = {W / 2 + 30, Tb / 2, 0, 6, 6};
BooleanDifference(8) = { Surface{3}; Delete; }{ Surface{4 : 7}; Delete; };
Physical Surface("u_plate") = {8};
