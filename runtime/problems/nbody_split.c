/* nbody_split.c — what the N-body problems of the collection share: their
 * Kepler splitting, through the runtime's N-body flows (vigen/nbody.h).
 * The problem's state (inertial positions, momenta m_i v_i) is the
 * runtime's inertial state, so that the changes of coordinates are the
 * runtime's. */
#include "problems_internal.h"

static int split(vigen_problem *pb, int coords, vigen_split_problem *out)
{
    return vigen_nbody_split(pb->nbody, coords, out);
}

static int convert(const vigen_problem *pb, int to_split, const double *q, const double *p, double *qs, double *ps)
{
    return to_split ? vigen_nbody_to_coordinates(pb->nbody, pb->split_coords, q, p, qs, ps)
                    : vigen_nbody_from_coordinates(pb->nbody, pb->split_coords, q, p, qs, ps);
}

int vigen_pbi_nbody_split_setup(vigen_problem *pb, size_t n, double G, const double *mass)
{
    int st = vigen_nbody_alloc(&pb->nbody, n, G, mass);
    if (st != VIGEN_SUCCESS) return st;
    pb->split = split;
    pb->split_convert = convert;
    return VIGEN_SUCCESS;
}
