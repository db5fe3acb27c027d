// tests/data/mesh/two_grains.msh is made from this file by
//   gmsh -2 -format msh41 two_grains.geo -o two_grains.msh
// Two grains (a square and a pentagon, physical surfaces "square" and "pentagon") above a
// floor slab (physical surface "floor"), meshed coarsely in triangles.
lc = 0.5;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc}; Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};

Point(11) = {2.0, 0.0, 0, lc}; Point(12) = {3.0, 0.0, 0, lc}; Point(13) = {3.3, 0.9, 0, lc};
Point(14) = {2.5, 1.5, 0, lc}; Point(15) = {1.7, 0.9, 0, lc};
Line(11) = {11, 12}; Line(12) = {12, 13}; Line(13) = {13, 14}; Line(14) = {14, 15}; Line(15) = {15, 11};
Curve Loop(2) = {11, 12, 13, 14, 15}; Plane Surface(2) = {2};

Point(21) = {-1, -1.0, 0, lc}; Point(22) = {5, -1.0, 0, lc}; Point(23) = {5, -0.5, 0, lc}; Point(24) = {-1, -0.5, 0, lc};
Line(21) = {21, 22}; Line(22) = {22, 23}; Line(23) = {23, 24}; Line(24) = {24, 21};
Curve Loop(3) = {21, 22, 23, 24}; Plane Surface(3) = {3};

Physical Surface("square") = {1};
Physical Surface("pentagon") = {2};
Physical Surface("floor") = {3};
