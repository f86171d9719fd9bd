// ArchDam Gmsh example: three cantilever blocks of a straight gravity-arch
// section on a rock block, with the reservoir upstream. Hexahedra only
// (transfinite + recombine). Ids follow doc/user-guide.md (doc/theory/conventions.md §4-§5):
// physical volumes = material ids, physical surfaces = boundary ids; solid
// faces outside any physical surface are traction-free (id 0).
//
// Axes: x downstream, y along the dam axis, z up, z = 0 at the dam base.
// Dam: x in [0, T], y in [-W/2, W/2], z in [0, H], blocks of width W/3
// numbered from +y (block 0, material 10, left looking downstream) to -y.
// Rock: x in [-L_u, T + L_d], z in [-D, 0]. Water: x in [-L_u, 0], z in [0, WL].
//
//   gmsh -3 -format msh22 gmsh_blocks.geo -o gmsh_blocks_v2.msh
//   gmsh -3 -format msh41 gmsh_blocks.geo -o gmsh_blocks_v4.msh
SetFactory("OpenCASCADE");

T  = 10;  // dam thickness [m]
W  = 30;  // dam length along its axis (3 blocks of 10 m) [m]
H  = 30;  // dam height [m]
WL = 25;  // water level [m]
D  = 20;  // rock depth [m]
Lu = 30;  // rock and reservoir length upstream of the dam [m]
Ld = 30;  // rock length downstream of the dam [m]
h  = 5;   // cell size [m]

xs[] = {-Lu, 0, T, T + Ld};
ys[] = {-W/2, -W/6, W/6, W/2};
zs[] = {-D, 0, WL, H};

// A structured arrangement of boxes: all of the bottom layer is rock, the
// middle column (x in [0, T]) is the dam, the upstream column up to WL water.
n = 0;
For i In {0:2}
  For j In {0:2}
    For k In {0:2}
      If (k == 0 || i == 1 || (i == 0 && k == 1))
        n += 1;
        Box(n) = {xs[i], ys[j], zs[k], xs[i+1] - xs[i], ys[j+1] - ys[j], zs[k+1] - zs[k]};
      EndIf
    EndFor
  EndFor
EndFor
// One conforming model: the boxes share their faces (and so their nodes).
BooleanFragments{ Volume{1:n}; Delete; }{}

// Hexahedra of size about h: every edge is split into round(length/h) cells
// (all box edges here are multiples of h).
cs[] = Curve{:};
For c In {0:#cs[]-1}
  bb[] = BoundingBox Curve{cs[c]};
  len = Sqrt((bb[3]-bb[0])^2 + (bb[4]-bb[1])^2 + (bb[5]-bb[2])^2);
  Transfinite Curve{cs[c]} = Round(len / h) + 1;
EndFor
Transfinite Surface{:};
Recombine Surface{:};
Transfinite Volume{:};

e = 1e-3;
// material ids
Physical Volume(1)  = Volume In BoundingBox{-Lu-e, -W/2-e, -D-e, T+Ld+e, W/2+e, e};
Physical Volume(2)  = Volume In BoundingBox{-Lu-e, -W/2-e, -e, e, W/2+e, WL+e};
Physical Volume(10) = Volume In BoundingBox{-e, W/6-e, -e, T+e, W/2+e, H+e};
Physical Volume(11) = Volume In BoundingBox{-e, -W/6-e, -e, T+e, W/6+e, H+e};
Physical Volume(12) = Volume In BoundingBox{-e, -W/2-e, -e, T+e, -W/6+e, H+e};
// boundary ids (0, traction-free: every other outer face of the solid)
Physical Surface(1) = Surface In BoundingBox{-Lu-e, -W/2-e, -D-e, T+Ld+e, W/2+e, -D+e};
Physical Surface(2) = {Surface In BoundingBox{-Lu-e, -W/2-e, -D-e, -Lu+e, W/2+e, e},
                       Surface In BoundingBox{T+Ld-e, -W/2-e, -D-e, T+Ld+e, W/2+e, e},
                       Surface In BoundingBox{-Lu-e, -W/2-e, -D-e, T+Ld+e, -W/2+e, e},
                       Surface In BoundingBox{-Lu-e, W/2-e, -D-e, T+Ld+e, W/2+e, e}};
Physical Surface(3) = Surface In BoundingBox{-Lu-e, -W/2-e, WL-e, e, W/2+e, WL+e};
Physical Surface(4) = Surface In BoundingBox{-Lu-e, -W/2-e, -e, -Lu+e, W/2+e, WL+e};
Physical Surface(5) = {Surface In BoundingBox{-Lu-e, -W/2-e, -e, e, -W/2+e, WL+e},
                       Surface In BoundingBox{-Lu-e, W/2-e, -e, e, W/2+e, WL+e}};
