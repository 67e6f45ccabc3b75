/* gni_anchors.h — the three hand-written anchors of bench/hand_gni_gauss.h
 * for a benchmark of one problem: gni2, gni3 (Gauss s = 2, 3) and gnil3
 * (Lobatto IIIA-IIIB s = 3), with the static dimension PEER_DIM, the force
 * peer_force inlined and M^-1 applied by PEER_VELOCITY(k, x), all defined
 * by the includer.  Shared by peer_bench.c and mech_icount.c. */
#define GNI_NAME gni2
#define GNI_S 2
#define GNI_DIM PEER_DIM
#define GNI_FORCE peer_force
#define GNI_VEL(k, x) PEER_VELOCITY(k, x)
#include "hand_gni_gauss.h"
#define GNI_NAME gni3
#define GNI_S 3
#include "hand_gni_gauss.h"
#define GNI_NAME gnil3
#define GNI_S 3
#define GNI_LOBATTO 1
#include "hand_gni_gauss.h"
