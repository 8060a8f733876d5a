// A pipe's wall (mid-surface, 3D): radius 20, length 200, with a radial cross hole
// (radius 6) through both sides at its middle. Genus 0 with 4 boundaries (the two
// ends and the two holes; chi = -2). Units mm.
SetFactory("OpenCASCADE");
Circle(1) = {0, 0, 0, 20};
Extrude {0, 0, 200} { Curve{1}; }
wall() = Surface{:};
Cylinder(10) = {0, -30, 100, 0, 60, 0, 6};
BooleanDifference{ Surface{wall()}; Delete; }{ Volume{10}; Delete; }
