// A bent sheet-metal part (mid-surface, 3D): a base flange 90 long and a second
// flange 70 long meeting at 120 degrees (a 60-degree bend of inner radius 8),
// 80 wide. Two bolt holes (radius 5) in the base flange and two holes
// (radius 4) in the inclined flange. Genus 0 with 5 boundaries (chi = -3). Units mm.
SetFactory("OpenCASCADE");
R = 8; A = 90; B = 70; D = 80; th = Pi / 3;      // bend angle 60 degrees
// profile in the x-y plane: base flange along -x to 0, then the bend about (0, R)
Point(1) = {-A, 0, 0}; Point(2) = {0, 0, 0}; Point(3) = {0, R, 0};
Point(4) = {R * Sin(th), R - R * Cos(th), 0};
Point(5) = {R * Sin(th) + B * Cos(th), R - R * Cos(th) + B * Sin(th), 0};
Line(1) = {1, 2};
Circle(2) = {2, 3, 4};
Line(3) = {4, 5};
Extrude {0, 0, D} { Curve{1, 2, 3}; }
// holes: cylinders through the base flange (axis y) and the inclined flange (axis normal)
Cylinder(10) = {-A + 25, -5, 22, 0, 10, 0, 5};
Cylinder(11) = {-A + 25, -5, D - 22, 0, 10, 0, 5};
nx = -Sin(th); ny = Cos(th);                     // normal of the inclined flange
cx = R * Sin(th) + 45 * Cos(th); cy = R - R * Cos(th) + 45 * Sin(th);
Cylinder(12) = {cx - 5 * nx, cy - 5 * ny, 25, 10 * nx, 10 * ny, 0, 4};
Cylinder(13) = {cx - 5 * nx, cy - 5 * ny, D - 25, 10 * nx, 10 * ny, 0, 4};
BooleanDifference{ Surface{1, 2, 3}; Delete; }{ Volume{10 : 13}; Delete; }
Physical Surface("sheet") = Surface{:};
