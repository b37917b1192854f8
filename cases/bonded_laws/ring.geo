// The control of the bonded laws' rates (issue 36; studies/convergence_rates.md, "The bonded laws'
// three misses"): the dovetail's laws on an interface without corners. A ring (plus, radii 0.2 and
// 0.5) in a round hole of a square base (minus, [-1, 1]^2), glued along an arc of 340 degrees that
// turns smoothly everywhere: its nodal normals never jump, unlike the slot's four corners. Its two
// ends sit at the sides of a shallow notch of the ring (radius 0.47, between 215 and 235 degrees),
// in the zone that the pull opens, so they carry no load. The base is clamped on y = -1 and the
// ring's inner edge pulled by (1e-3, 1e-3), as the tenon's top: the upper right of the arc is
// pressed, the lower left opens, and the two contact edges lie on the smooth arc. Length unit L = 1.
h = 0.1;  // fallback element size (the scene's mesh_size overrides it)
r = 0.5;  // the glued arc
q = 0.47; // the notch's bottom
ri = 0.2; // the ring's inner edge (the grip)

Point(1) = {0, 0, 0, h};
Point(2) = {-1, -1, 0, h};
Point(3) = {1, -1, 0, h};
Point(4) = {1, 1, 0, h};
Point(5) = {-1, 1, 0, h};
a1 = 215 * Pi / 180;  // the arc's ends, the notch's sides
a2 = 235 * Pi / 180;
b1 = 325 * Pi / 180;  // intermediate points: gmsh's arcs span less than 180 degrees
b2 = 55 * Pi / 180;
b3 = 145 * Pi / 180;
Point(10) = {r * Cos(a1), r * Sin(a1), 0, h};
Point(11) = {r * Cos(a2), r * Sin(a2), 0, h};
Point(12) = {r * Cos(b1), r * Sin(b1), 0, h};
Point(13) = {r * Cos(b2), r * Sin(b2), 0, h};
Point(14) = {r * Cos(b3), r * Sin(b3), 0, h};
Point(15) = {q * Cos(a1), q * Sin(a1), 0, h};
Point(16) = {q * Cos(a2), q * Sin(a2), 0, h};
Point(20) = {ri, 0, 0, h};
Point(21) = {0, ri, 0, h};
Point(22) = {-ri, 0, 0, h};
Point(23) = {0, -ri, 0, h};

Line(1) = {2, 3};   // base bottom: clamped
Line(2) = {3, 4};
Line(3) = {4, 5};
Line(4) = {5, 2};
Circle(5) = {11, 1, 12};  // } the bondline S: from 235 degrees counter-clockwise
Circle(6) = {12, 1, 13};  // } round to 215 degrees (340 degrees)
Circle(7) = {13, 1, 14};  // }
Circle(8) = {14, 1, 10};  // }
Circle(9) = {10, 1, 11};  // the hole's edge over the notch (base side), free
Line(10) = {10, 15};      // the notch (ring side), free
Circle(11) = {15, 1, 16};
Line(12) = {16, 11};
Circle(13) = {20, 1, 21};  // the ring's inner edge: pulled
Circle(14) = {21, 1, 22};
Circle(15) = {22, 1, 23};
Circle(16) = {23, 1, 20};

Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, 8, 9};
Plane Surface(1) = {1, 2};
Curve Loop(3) = {5, 6, 7, 8, 10, 11, 12};
Curve Loop(4) = {13, 14, 15, 16};
Plane Surface(2) = {3, 4};

Physical Surface("base") = {1};
Physical Surface("ring") = {2};
Physical Curve("S") = {5, 6, 7, 8};
Physical Curve("base_bottom") = {1};
Physical Curve("grip") = {13, 14, 15, 16};
