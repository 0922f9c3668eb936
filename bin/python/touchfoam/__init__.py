"""touchfoam: Python helpers for the touchFoam cases (stdlib + numpy only).

Modules
    foamfile   read/write OpenFOAM ASCII field files and simple dictionaries
    mesh       read constant/polyMesh; cell centres and volumes computed the
               way OpenFOAM computes them
    monitor    read postProcessing/solidMonitor/*/solidMonitor.dat
    run        run commands with log files, copy cases, set case options
    analytic   closed-form solutions of the benchmarks (swinging cube, ...)
    cases      set-up of each tutorial (mesh, initial fields)
    gmsh       Gmsh 2.2 ASCII tetrahedral mesh of a cube
    checks     the checks of a validation study (measured, reference, pass) in
               its checks.json, and the table validation/Allrun reports

Scripts find this package by walking up from their own folder to
bin/python (so copies of a tutorial inside the repository work), else
through $TOUCH_PROJECT_DIR, set by etc/bashrc.
"""

# numpy is imported by the modules that need it, so that a clear error is
# given by the first script that uses them when it is missing.
