// Scarf joint (plane strain, lengths in mm): two steel strips 3 mm thick in line, glued along a
// scarf whose run is 10 mm (a slope of 3/10: 16.7 degrees to the strips' axis). The left strip is
// clamped at its left end, the right one pulled along the axis at its right end. The bondline is
// their shared slanted curve; its normal points from the left strip (minus) into the right one
// (plus), 73.3 degrees from the axis.
//
//   clamp ______________________________ ______________________________ y = 3
//        |  left strip                  /                               | grip (pulled)
//        |_____________________________/________________________________| y = 0
//       x = 0                   x = 30  x = 40  (the scarf: (30, 3) to (40, 0))   x = 70
//
// In layer mode the plus strip moves to make room for the glue: along the bondline's normal by
// default, which would lift it off the clamped strip's axis; the scene moves it along the axis
// instead ("make_room": [1, 0], README "Layer mode: making room").
L = 30;       // each strip's straight length
t = 3;        // strip thickness
run = 10;     // the scarf's run along the axis
h = 1;        // fallback element size (the scene's mesh_size overrides it)

Point(1) = {0, 0, 0, h};
Point(2) = {L + run, 0, 0, h};
Point(3) = {L, t, 0, h};
Point(4) = {0, t, 0, h};
Point(5) = {2 * L + run, 0, 0, h};
Point(6) = {2 * L + run, t, 0, h};

Line(1) = {1, 2};    // left strip bottom, free
Line(2) = {2, 3};    // the scarf, from (40, 0) to (30, 3)
Line(3) = {3, 4};    // left strip top, free
Line(4) = {4, 1};    // left end: the clamp
Line(5) = {2, 5};    // right strip bottom, free
Line(6) = {5, 6};    // right end: the grip
Line(7) = {6, 3};    // right strip top, free

Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, -2};
Plane Surface(2) = {2};

Physical Surface("left") = {1};
Physical Surface("right") = {2};
Physical Curve("scarf") = {2};
Physical Curve("clamp") = {4};
Physical Curve("grip") = {6};
