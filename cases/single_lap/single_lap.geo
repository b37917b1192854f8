// Single-lap joint, glued (plane strain, lengths in mm): two steel sheets 1 mm thick and 30 mm
// long overlapping over 12.5 mm, the bondline their shared curve. The lower sheet is clamped at
// its left end, the upper one pulled at its right end (the grip). In layer mode the upper sheet
// (the plus body) moves up by the glue's thickness to make room for it.
//
//                                   upper sheet                  grip (pulled)
//                        _______________________________________________ y = 2
//  _____________________|___________ bondline __________________________| y = 1
// |  lower sheet                    |                                      (x = 17.5 .. 30)
// |_________________________________|                                      y = 0
// x = 0 clamp          x = 17.5     x = 30                         x = 47.5
//
// Physical surfaces are the bodies, physical curves the bondline, supports and loads
// (thinlayer scene files, README "Your own joint").
L = 30;       // sheet length
t = 1;        // sheet thickness
a = 17.5;     // start of the overlap: overlap length L - a = 12.5
h = 1;        // fallback element size (the scene's mesh_size overrides it)

Point(1) = {0, 0, 0, h};
Point(2) = {L, 0, 0, h};
Point(3) = {L, t, 0, h};
Point(4) = {a, t, 0, h};
Point(5) = {0, t, 0, h};
Point(6) = {a + L, t, 0, h};
Point(7) = {a + L, 2 * t, 0, h};
Point(8) = {a, 2 * t, 0, h};

Line(1) = {1, 2};    // lower bottom, free
Line(2) = {2, 3};    // lower right end, free
Line(3) = {4, 3};    // the bondline, from (17.5, 1) to (30, 1)
Line(4) = {4, 5};    // lower top, free
Line(5) = {5, 1};    // lower left end: the clamp
Line(6) = {3, 6};    // upper bottom beyond the overlap, free
Line(7) = {6, 7};    // upper right end: the grip
Line(8) = {7, 8};    // upper top, free
Line(9) = {8, 4};    // upper left end, free

Curve Loop(1) = {1, 2, -3, 4, 5};
Plane Surface(1) = {1};
Curve Loop(2) = {3, 6, 7, 8, 9};
Plane Surface(2) = {2};

Physical Surface("lower") = {1};
Physical Surface("upper") = {2};
Physical Curve("bondline") = {3};
Physical Curve("clamp") = {5};
Physical Curve("grip") = {7};
