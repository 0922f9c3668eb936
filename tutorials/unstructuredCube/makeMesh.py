#!/usr/bin/python3
"""Write cube.msh: the unit cube as n^3 hexes, each split into 6 tets.

    ./makeMesh.py [-n N] [-o cube.msh]

Gmsh 2.2 ASCII with physical surfaces X0 Y0 Z0 X1 Y1 Z1 and the physical
volume 'cube'; convert with 'gmshToFoam cube.msh'.  The split is the
conforming Kuhn one (see bin/python/touchfoam/gmsh.py).
"""

import argparse


# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam.gmsh import write_msh

if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("-n", type=int, default=8,
                        help="hexes per side before the split (default 8)")
    parser.add_argument("-o", default="cube.msh", help="output file")
    args = parser.parse_args()
    if args.n < 1:
        parser.error("-n must be positive")
    npoints, ntets = write_msh(args.o, args.n)
    print("makeMesh: %s with %d points and %d tetrahedra"
          % (args.o, npoints, ntets))
