// The plug of round_tenon.geo in a socket with no undercut (plane strain, lengths in mm): the
// socket's cavity is the bottom of the head's circle only, 60 deg either side of its lowest point,
// its rim at y = -R cos 60 deg. Pulled up along its neck, every force the contact can put on the
// head points up and in: within the friction cone f = 0.3 a push at 60 deg from the bottom can pull
// down only where tan 60 deg > 1/f, which it is not (1.73 < 3.33). Statics proves it comes out.
//
//                   grip (pulled up)
//                     |
//                    | |  neck
//                  /     \
//                 | head  |
//       __________ \     / __________  y = -R cos 60: the socket's top, its rim
//      |            \___/            |  the bondline: the circle within 60 deg of the bottom
//      |  socket                     |
//      |_____________________________| y = -10: clamp
R = 5;        // head radius
w = 1.5;      // neck half-width
H = 15;       // neck top
B = 10;       // socket half-width and depth below the centre
h = 1;        // fallback element size (the scene's mesh_size overrides it)
c = R * Sin(Pi / 3);
yr = -R * Cos(Pi / 3);
yq = Sqrt(R * R - w * w);

Point(1) = {0, 0, 0, h};          // the head's centre
Point(2) = {-c, yr, 0, h};        // the rim, left (-150 deg)
Point(3) = {0, -R, 0, h};
Point(4) = {c, yr, 0, h};         // the rim, right (-30 deg)
Point(5) = {w, yq, 0, h};         // where the neck meets the head
Point(6) = {w, H, 0, h};
Point(7) = {-w, H, 0, h};
Point(8) = {-w, yq, 0, h};
Point(9) = {B, yr, 0, h};
Point(10) = {B, -B, 0, h};
Point(11) = {-B, -B, 0, h};
Point(12) = {-B, yr, 0, h};

Circle(1) = {2, 1, 3};    // the bondline
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};    // the head's free side, right
Line(4) = {5, 6};         // neck, right side
Line(5) = {6, 7};         // neck top: the grip
Line(6) = {7, 8};         // neck, left side
Circle(7) = {8, 1, 2};    // the head's free side, left
Line(8) = {4, 9};         // socket top, right
Line(9) = {9, 10};
Line(10) = {10, 11};      // socket base: the clamp
Line(11) = {11, 12};
Line(12) = {12, 2};       // socket top, left

Curve Loop(1) = {1, 2, 3, 4, 5, 6, 7};
Plane Surface(1) = {1};
Curve Loop(2) = {-2, -1, -12, -11, -10, -9, -8};
Plane Surface(2) = {2};

Physical Surface("plug") = {1};
Physical Surface("socket") = {2};
Physical Curve("bondline") = {1, 2};
Physical Curve("grip") = {5};
Physical Curve("clamp") = {10};
