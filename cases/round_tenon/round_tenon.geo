// A round tenon wedged in its socket (plane strain, lengths in mm): a plug — a round head of
// radius R on a neck 2w wide — sits in a socket whose cavity is the same circle wrapped beyond the
// head's equator (the undercut), opened over the top quarter where the neck leaves through a slot
// wider than the neck. Pulled out along its neck, the head bears on the undercut: the plug cannot
// come out. Nothing but the contact holds the plug (no support); the socket is clamped at its base.
//
//                    grip (pulled up)
//                     __|__  y = 15
//                    |     |  neck, x = -w .. w
//        ____________|     |____________ y = 8
//       |        |   |     |   |        |
//       |        |___|     |___|        |  slot walls x = -s .. s, s = R sin 45
//       |       /   head, radius R   \  |   the bondline: the circle from 135 deg round
//       |      |         +          |   |   the bottom to 45 deg (270 deg of it)
//       |       \________________ /     |
//       |  socket                       |
//       |_______________________________| y = -10: clamp
//      x = -10                         x = 10
//
// Physical surfaces are the bodies, physical curves the bondline, supports and loads.
R = 5;        // head radius
w = 1.5;      // neck half-width
H = 15;       // neck top
T = 8;        // socket top
B = 10;       // socket half-width and depth below the centre
h = 1;        // fallback element size (the scene's mesh_size overrides it)
s = R * Sin(Pi / 4);
yq = Sqrt(R * R - w * w);

Point(1) = {0, 0, 0, h};          // the head's centre
Point(2) = {-s, s, 0, h};         // 135 deg: the undercut's left lip
Point(3) = {-R, 0, 0, h};
Point(4) = {0, -R, 0, h};
Point(5) = {R, 0, 0, h};
Point(6) = {s, s, 0, h};          // 45 deg: the right lip
Point(7) = {w, yq, 0, h};         // where the neck meets the head
Point(8) = {w, H, 0, h};
Point(9) = {-w, H, 0, h};
Point(10) = {-w, yq, 0, h};
Point(11) = {s, T, 0, h};         // the slot's top corners
Point(12) = {-s, T, 0, h};
Point(13) = {B, T, 0, h};
Point(14) = {B, -B, 0, h};
Point(15) = {-B, -B, 0, h};
Point(16) = {-B, T, 0, h};

Circle(1) = {2, 1, 3};    // the bondline, from the left lip round the bottom to the right lip
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 6};
Circle(5) = {6, 1, 7};    // the head's free top, right
Line(6) = {7, 8};         // neck, right side
Line(7) = {8, 9};         // neck top: the grip
Line(8) = {9, 10};        // neck, left side
Circle(9) = {10, 1, 2};   // the head's free top, left
Line(10) = {6, 11};       // slot wall, right
Line(11) = {11, 13};      // socket top, right
Line(12) = {13, 14};      // socket right side
Line(13) = {14, 15};      // socket base: the clamp
Line(14) = {15, 16};      // socket left side
Line(15) = {16, 12};      // socket top, left
Line(16) = {12, 2};       // slot wall, left

Curve Loop(1) = {1, 2, 3, 4, 5, 6, 7, 8, 9};
Plane Surface(1) = {1};
Curve Loop(2) = {-4, -3, -2, -1, -16, -15, -14, -13, -12, -11, -10};
Plane Surface(2) = {2};

Physical Surface("plug") = {1};
Physical Surface("socket") = {2};
Physical Curve("bondline") = {1, 2, 3, 4};
Physical Curve("grip") = {7};
Physical Curve("clamp") = {13};
