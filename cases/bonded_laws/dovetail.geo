// The paper's dovetail assembly (SPEC §2.2) as a scene-file geometry, for the convergence study of
// the bonded laws (README "Bonded faces"): the base (minus) with its dovetail slot, the tenon
// (plus) filling the slot with its stem, the bondline S along the slot's two flanks and bottom.
// Length unit L = 1 (written as mm). The base is clamped on y = -1, the tenon's top pulled.
h = 0.1;  // fallback element size (the scene's mesh_size overrides it)

Point(1) = {-1, -1, 0, h};
Point(2) = {1, -1, 0, h};
Point(3) = {1, 0, 0, h};
Point(4) = {0.4, 0, 0, h};
Point(5) = {0.6, -0.5, 0, h};
Point(6) = {-0.6, -0.5, 0, h};
Point(7) = {-0.4, 0, 0, h};
Point(8) = {-1, 0, 0, h};
Point(9) = {0.4, 0.5, 0, h};
Point(10) = {-0.4, 0.5, 0, h};

Line(1) = {1, 2};   // base bottom: clamped
Line(2) = {2, 3};   // base right side
Line(3) = {3, 4};   // base top, right of the slot
Line(4) = {4, 5};   // right flank   } the bondline S, from the left flank's top
Line(5) = {5, 6};   // slot bottom   } to the right flank's top
Line(6) = {6, 7};   // left flank    }
Line(7) = {7, 8};   // base top, left of the slot
Line(8) = {8, 1};   // base left side
Line(9) = {4, 9};   // stem right side
Line(10) = {9, 10}; // stem top: pulled
Line(11) = {10, 7}; // stem left side

Curve Loop(1) = {1, 2, 3, 4, 5, 6, 7, 8};
Plane Surface(1) = {1};
Curve Loop(2) = {-6, -5, -4, 9, 10, 11};
Plane Surface(2) = {2};

Physical Surface("base") = {1};
Physical Surface("tenon") = {2};
Physical Curve("S") = {4, 5, 6};
Physical Curve("base_bottom") = {1};
Physical Curve("tenon_top") = {10};
