/*---------------------------------------------------------------------------*\
  touchFoam: explicit large-strain solid dynamics (TOUCH) on OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later, as OpenFOAM.

Description
    The memory bandwidth of one core, STREAM's triad a[i] = b[i] + s c[i]
    on three arrays of n doubles (default 10,000,000: 80 MB each, far
    beyond the caches), the best of r repetitions (default 20).

    Prints one line:
        triad n <n> repetitions <r> best_s <t> GBps_3arrays <x>
            GBps_4arrays <y> checksum <sum>
    (on one line)
    GBps_3arrays counts 3 x 8 bytes per element (STREAM's convention: read
    b, c, write a); GBps_4arrays adds the read of a that a cached store
    costs (write-allocate), which is what the memory moves: gcc -O2 emits
    ordinary, not streaming, stores.

Usage
    gcc -O2 -o triad triad.c && ./triad [n [r]]

\*---------------------------------------------------------------------------*/

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9*t.tv_nsec;
}

int main(int argc, char *argv[])
{
    const long n = argc > 1 ? atol(argv[1]) : 10000000L;
    const int r = argc > 2 ? atoi(argv[2]) : 20;
    const double s = 3.0;

    double *a = malloc(n*sizeof(double));
    double *b = malloc(n*sizeof(double));
    double *c = malloc(n*sizeof(double));
    if (!a || !b || !c || n < 1 || r < 1)
    {
        fprintf(stderr, "triad: cannot allocate 3 x %ld doubles\n", n);
        return 1;
    }

    /* First touch: the pages are mapped before the timing */
    for (long i = 0; i < n; ++i)
    {
        a[i] = 0.0;
        b[i] = 1.0;
        c[i] = 2.0;
    }

    double best = 1e30;
    for (int k = 0; k < r; ++k)
    {
        const double t0 = now();
        for (long i = 0; i < n; ++i)
        {
            a[i] = b[i] + s*c[i];
        }
        const double t = now() - t0;
        if (t < best)
        {
            best = t;
        }
        /* Keep the loop from being hoisted: the next pass reads a */
        b[k % n] = a[(k*7919L) % n];
    }

    double sum = 0;
    for (long i = 0; i < n; ++i)
    {
        sum += a[i];
    }

    printf
    (
        "triad n %ld repetitions %d best_s %.6e GBps_3arrays %.3f "
        "GBps_4arrays %.3f checksum %.6e\n",
        n, r, best, 24.0*n/best/1e9, 32.0*n/best/1e9, sum
    );

    free(a);
    free(b);
    free(c);
    return 0;
}
