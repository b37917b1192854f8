// Single-lap shear joint (the classic adhesive-joint test), plane strain, lengths in mm.
// Two aluminium strips 30 mm long and 2 mm thick overlap over 12.5 mm; the bondline is their
// shared curve. (Longer, more slender strips make the bulk's condition number grow like the
// square of their slenderness: at 60 mm the limit-mode residual stalls near 1e-10.)
//
//                          press (overlap top)             grip (pulled)
//                        ______________________________________________ y = 4
//                       |  upper strip                                  |
//  _____________________|_______________________________________________| y = 2
// |  lower strip        | bondline  |                                     (x = 17.5 .. 30)
// |_____________________|___________|                                     y = 0
// x = 0 clamp           anvil (overlap bottom)                   x = 47.5
//
// Physical surfaces are the bodies, physical curves the interface, supports and loads
// (thinlayer scene files, README "Your own joint").
L = 30;       // strip length
t = 2;        // strip thickness
a = 17.5;     // start of the overlap: overlap length L - a = 12.5
h = 1;        // fallback element size (the scene's mesh_size overrides it)

Point(1) = {0, 0, 0, h};
Point(2) = {a, 0, 0, h};
Point(3) = {L, 0, 0, h};
Point(4) = {L, t, 0, h};
Point(5) = {a, t, 0, h};
Point(6) = {0, t, 0, h};
Point(7) = {a + L, t, 0, h};
Point(8) = {a + L, 2 * t, 0, h};
Point(9) = {L, 2 * t, 0, h};
Point(10) = {a, 2 * t, 0, h};

Line(1) = {1, 2};    // lower bottom, free
Line(2) = {2, 3};    // lower bottom under the overlap: the anvil
Line(3) = {3, 4};    // lower right end, free
Line(4) = {5, 4};    // the bondline, from (17.5, 2) to (30, 2)
Line(5) = {5, 6};    // lower top, free
Line(6) = {6, 1};    // lower left end: the clamp
Line(7) = {4, 7};    // upper bottom, free
Line(8) = {7, 8};    // upper right end: the grip
Line(9) = {8, 9};    // upper top, free
Line(10) = {9, 10};  // upper top over the overlap: pressed
Line(11) = {10, 5};  // upper left end, free

Curve Loop(1) = {1, 2, 3, -4, 5, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {4, 7, 8, 9, 10, 11};
Plane Surface(2) = {2};

Physical Surface("lower") = {1};
Physical Surface("upper") = {2};
Physical Curve("bondline") = {4};
Physical Curve("clamp") = {6};
Physical Curve("anvil") = {2};
Physical Curve("grip") = {8};
Physical Curve("press") = {10};
