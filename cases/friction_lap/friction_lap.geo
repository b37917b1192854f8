// Double-lap joint held by friction alone (plane strain, lengths in mm): an inner strip 3 mm thick
// between two outer strips 1.5 mm thick over a 25 mm overlap, with no glue holding it: the faces of
// both bondlines are in contact with Coulomb friction, and a clamping pressure on the outer strips'
// outer faces over the overlap presses them onto the inner strip. The outer strips are clamped at
// their right ends; the inner strip has no support: its pull at the left end is carried by friction
// alone (issue 33, finding 5). Capacity: 2 faces × f × p × overlap.
//
//                          clamp_top (pressure)     outer_top            clamp
//                        ___________________________________________ y = 3
//                       |________ bond_top _________|_______________| y = 1.5
//   grip  _____________________________________________|                 (inner: x = 0 .. 35)
//        |  inner strip                             |
//        |__________________________________________|_______________ y = -1.5
//                       |________ bond_bottom ______________________|
//                       |___________________________|_______________| y = -3
//       x = 0          x = 10                    x = 35           x = 45
ti = 3;       // inner strip thickness
to = 1.5;     // outer strip thickness
a = 10;       // start of the overlap
b = 35;       // end of the overlap (the inner strip's right end)
c = 45;       // the outer strips' right ends
h = 1;

Point(1) = {0, -ti / 2, 0, h};
Point(2) = {a, -ti / 2, 0, h};
Point(3) = {b, -ti / 2, 0, h};
Point(4) = {b, ti / 2, 0, h};
Point(5) = {a, ti / 2, 0, h};
Point(6) = {0, ti / 2, 0, h};
Point(7) = {c, ti / 2, 0, h};
Point(8) = {c, ti / 2 + to, 0, h};
Point(9) = {a, ti / 2 + to, 0, h};
Point(10) = {c, -ti / 2, 0, h};
Point(11) = {c, -ti / 2 - to, 0, h};
Point(12) = {a, -ti / 2 - to, 0, h};
Point(13) = {b, ti / 2 + to, 0, h};
Point(14) = {b, -ti / 2 - to, 0, h};

Line(1) = {1, 2};     // inner bottom, free
Line(2) = {2, 3};     // bond_bottom
Line(3) = {3, 4};     // inner right end, free
Line(4) = {5, 4};     // bond_top
Line(5) = {5, 6};     // inner top, free
Line(6) = {6, 1};     // the grip
Line(7) = {4, 7};     // upper strip bottom beyond the overlap, free
Line(8) = {7, 8};     // upper strip right end: clamped
Line(9) = {8, 13};    // upper strip top beyond the overlap, free
Line(15) = {13, 9};   // upper strip top over the overlap: pressed
Line(10) = {9, 5};    // upper strip left end, free
Line(11) = {3, 10};   // lower strip top beyond the overlap, free
Line(12) = {10, 11};  // lower strip right end: clamped
Line(13) = {11, 14};  // lower strip bottom beyond the overlap, free
Line(16) = {14, 12};  // lower strip bottom over the overlap: pressed
Line(14) = {12, 2};   // lower strip left end, free

Curve Loop(1) = {1, 2, 3, -4, 5, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {4, 7, 8, 9, 15, 10};
Plane Surface(2) = {2};
Curve Loop(3) = {-2, -14, -16, -13, -12, -11};
Plane Surface(3) = {3};

Physical Surface("inner") = {1};
Physical Surface("outer_top") = {2};
Physical Surface("outer_bottom") = {3};
Physical Curve("bond_top") = {4};
Physical Curve("bond_bottom") = {2};
Physical Curve("grip") = {6};
Physical Curve("clamp") = {8, 12};
Physical Curve("press_top") = {15};
Physical Curve("press_bottom") = {16};
