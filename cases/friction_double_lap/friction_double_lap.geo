// Double-lap joint held by friction alone (plane strain, lengths in mm): the double lap of
// cases/double_lap (an inner strip 3 mm thick between two outer strips 1.5 mm thick over a 10 mm
// overlap), its outer strips pressed onto the inner one over the overlap (press_top, press_bottom)
// and clamped at their right ends; the inner strip has no support: only the friction on its two
// faces holds it against the pull on its left end (grip). The layer between the strips is in
// contact on both faces (a glue that does not stick: the paper's layer).
//
//                                  press_top
//                               ____________ ________________________________ y = 3
//                              |________ bond_top __________________________| y = 1.5
//   grip  ____________________________________|                                (inner: x = 0 .. 20)
//        |  inner strip                       |
//        |____________________________________|__________________________ y = -1.5
//                              |________ bond_bottom _______________________|
//                              |____________|_______________________________| y = -3
//       x = 0                 x = 10  press_bottom x = 20                 x = 30
//
// Physical surfaces are the bodies, physical curves the bondlines, supports and loads
// (thinlayer scene files, README "Your own joint").
ti = 3;       // inner strip thickness
to = 1.5;     // outer strip thickness
a = 10;       // start of the overlap
b = 20;       // end of the overlap (the inner strip's right end)
c = 30;       // the outer strips' right ends
h = 1;        // fallback element size (the scene's mesh_size overrides it)

// inner strip
Point(1) = {0, -ti / 2, 0, h};
Point(2) = {a, -ti / 2, 0, h};
Point(3) = {b, -ti / 2, 0, h};
Point(4) = {b, ti / 2, 0, h};
Point(5) = {a, ti / 2, 0, h};
Point(6) = {0, ti / 2, 0, h};
// upper outer strip
Point(7) = {c, ti / 2, 0, h};
Point(8) = {c, ti / 2 + to, 0, h};
Point(9) = {a, ti / 2 + to, 0, h};
// lower outer strip
Point(10) = {c, -ti / 2, 0, h};
Point(11) = {c, -ti / 2 - to, 0, h};
Point(12) = {a, -ti / 2 - to, 0, h};
// the ends of the pressed faces over the overlap
Point(13) = {b, ti / 2 + to, 0, h};
Point(14) = {b, -ti / 2 - to, 0, h};

Line(1) = {1, 2};    // inner bottom, free
Line(2) = {2, 3};    // bond_bottom (inner side up: from x = a to b)
Line(3) = {3, 4};    // inner right end, free (inside the overlap's end gap)
Line(4) = {5, 4};    // bond_top
Line(5) = {5, 6};    // inner top, free
Line(6) = {6, 1};    // the grip
Line(7) = {4, 7};    // upper strip bottom beyond the overlap, free
Line(8) = {7, 8};    // upper strip right end: clamped
Line(9) = {8, 13};   // upper strip top beyond the overlap, free
Line(15) = {13, 9};  // upper strip top over the overlap: pressed
Line(10) = {9, 5};   // upper strip left end, free
Line(11) = {3, 10};  // lower strip top beyond the overlap, free
Line(12) = {10, 11}; // lower strip right end: clamped
Line(13) = {11, 14}; // lower strip bottom beyond the overlap, free
Line(16) = {14, 12}; // lower strip bottom over the overlap: pressed
Line(14) = {12, 2};  // lower strip left end, free

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
