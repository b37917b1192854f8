// Stepped-lap joint (plane strain, lengths in mm): two aluminium plates 3 mm thick, each cut in two
// steps of 1 mm, glued on the two horizontal steps (two bondlines, 9.5 mm each). The risers are
// left open (0.5 mm gaps): only the steps are glued. The lower plate is clamped at its left end,
// the upper one pulled at its right end. The upper plate is the plus body of both bondlines (in
// layer mode it moves up by the glue's thickness).
//
//   clamp ______________________________________________________ y = 3     upper: x = 10.5 .. 40
//        |  lower              |  |  upper                      |
//        |_____________________|__|________________ bond_upper  | y = 2     (x = 10.5 .. 20)
//        |                                |  |     bond_lower   | grip
//        |________________________________|__|_____________     | y = 1     (x = 20.5 .. 30)
//        |                                            |  |      |
//        |____________________________________________|__|______| y = 0
//       x = 0                 10  10.5   20 20.5     30 30.5    40
//
// Physical surfaces are the bodies, physical curves the bondlines, supports and loads
// (thinlayer scene files, README "Your own joint").
h = 1;  // fallback element size (the scene's mesh_size overrides it)

Point(1) = {0, 0, 0, h};
Point(2) = {30, 0, 0, h};
Point(3) = {30, 1, 0, h};
Point(4) = {20.5, 1, 0, h};
Point(5) = {20, 1, 0, h};
Point(6) = {20, 2, 0, h};
Point(7) = {10.5, 2, 0, h};
Point(8) = {10, 2, 0, h};
Point(9) = {10, 3, 0, h};
Point(10) = {0, 3, 0, h};
Point(11) = {20.5, 2, 0, h};
Point(12) = {30.5, 1, 0, h};
Point(13) = {30.5, 0, 0, h};
Point(14) = {40, 0, 0, h};
Point(15) = {40, 3, 0, h};
Point(16) = {10.5, 3, 0, h};

Line(1) = {1, 2};    // lower plate bottom, free
Line(2) = {2, 3};    // lower plate's last riser, free
Line(3) = {4, 3};    // bond_lower: y = 1, x = 20.5 .. 30
Line(4) = {4, 5};    // lower step top beyond the bondline, free
Line(5) = {5, 6};    // lower plate's middle riser, free
Line(6) = {7, 6};    // bond_upper: y = 2, x = 10.5 .. 20
Line(7) = {7, 8};    // upper step top beyond the bondline, free
Line(8) = {8, 9};    // lower plate's first riser, free
Line(9) = {9, 10};   // lower plate top, free
Line(10) = {10, 1};  // lower plate's left end: the clamp
Line(11) = {6, 11};  // upper plate bottom over the middle gap, free
Line(12) = {11, 4};  // upper plate's middle riser, free
Line(13) = {3, 12};  // upper plate bottom over the last gap, free
Line(14) = {12, 13}; // upper plate's last riser, free
Line(15) = {13, 14}; // upper plate bottom, free
Line(16) = {14, 15}; // upper plate's right end: the grip
Line(17) = {15, 16}; // upper plate top, free
Line(18) = {16, 7};  // upper plate's first riser, free

Curve Loop(1) = {1, 2, -3, 4, 5, -6, 7, 8, 9, 10};
Plane Surface(1) = {1};
Curve Loop(2) = {6, 11, 12, 3, 13, 14, 15, 16, 17, 18};
Plane Surface(2) = {2};

Physical Surface("lower") = {1};
Physical Surface("upper") = {2};
Physical Curve("bond_upper") = {6};
Physical Curve("bond_lower") = {3};
Physical Curve("clamp") = {10};
Physical Curve("grip") = {16};
