// Plate with a central hole, meshed by gmsh for gmshToFoam:
//     gmsh -3 -setnumber n 8 plate.geo -o plate.msh
// n: cells across the half height between the hole and an edge (default 8).
// One layer of hexahedra (quadrilaterals extruded) through the thickness.
// Physical groups: surfaces left, right, sides (y = +-H/2), hole,
// frontAndBack (z = 0, t) become patches; the volume 'plate' a cellZone.

If (!Exists(n))
    n = 8;
EndIf

L = 0.2;        // length along x [m]
H = 0.1;        // height along y [m]
R = 0.02;       // hole radius [m]
t = 0.005;      // thickness along z [m]
h = (H/2 - R)/n;

Mesh.MshFileVersion = 2.2;
Mesh.RecombineAll = 1;
// Frontal-Delaunay, then recombined (Debian 12's gmsh 4.8.4 ends with a
// segmentation fault on this plate with algorithm 8, 2026-12-04)
Mesh.Algorithm = 6;
Mesh.RecombinationAlgorithm = 1;

Point(1) = {-L/2, -H/2, 0, h};
Point(2) = { L/2, -H/2, 0, h};
Point(3) = { L/2,  H/2, 0, h};
Point(4) = {-L/2,  H/2, 0, h};
Point(5) = {0, 0, 0, h};
Point(6) = { R, 0, 0, h};
Point(7) = {0,  R, 0, h};
Point(8) = {-R, 0, 0, h};
Point(9) = {0, -R, 0, h};

Line(1) = {1, 2};       // bottom
Line(2) = {2, 3};       // right
Line(3) = {3, 4};       // top
Line(4) = {4, 1};       // left
Circle(5) = {6, 5, 7};
Circle(6) = {7, 5, 8};
Circle(7) = {8, 5, 9};
Circle(8) = {9, 5, 6};

Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(1) = {1, 2};

// out[0]: the face at z = t, out[1]: the volume, out[2..]: the faces swept
// from curves 1..8 in order
out[] = Extrude {0, 0, t} { Surface{1}; Layers{1}; Recombine; };

Physical Surface("left") = {out[5]};
Physical Surface("right") = {out[3]};
Physical Surface("sides") = {out[2], out[4]};
Physical Surface("hole") = {out[6], out[7], out[8], out[9]};
Physical Surface("frontAndBack") = {1, out[0]};
Physical Volume("plate") = {out[1]};
