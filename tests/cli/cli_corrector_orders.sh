#!/bin/bash
# cli_corrector_orders.sh VIGEN SRC — the symplectic correctors of the
# runtime's N-body library (vigen_nbody_corrector_apply), written as
# processed splitting files with the runtime's 17-digit coefficients
# (tests/data/splitting/wh_*_corrector_K.lua), have the generalized orders
# the theory of Wisdom, Holman & Touma (1996) gives: the Wisdom-Holman
# kernel's error is eps (h^2 E_2 + h^4 E_4 + ...) + O(eps^2 h^2) (a
# symmetric kernel: even powers only), a corrector of order K removes the
# eps h^j terms for j <= K - 1 and, being O(eps) itself, leaves the eps^2 h^2
# term alone: generalized order (K + 1, 2).  The checker decides this from
# the Lie series of the step, independently of the runtime's derivation of
# the b_i.  Controls: the kernel alone is (2,2), and the drift-kick-drift
# kernel with the kick-drift-kick kernel's coefficients is not corrected
# (the eps h^2 term remains: (2,2)).
set -u
VIGEN=$1
SRC=$2
T=$(mktemp -d /tmp/vigen-cli-corrector-XXXXXX)
trap 'rm -rf "$T"' EXIT
fail=0
bad() { echo "FAIL: $*"; fail=1; }
D=$SRC/tests/data/splitting

# order FILE EXPECTED: the checker's generalized order of FILE is EXPECTED
order() {
  "$VIGEN" check "$1" > "$T/out" 2>&1
  local rc=$?
  local got
  got=$(sed -n 's/^  generalized order (\([^)]*\)).*/\1/p' "$T/out" | head -1)
  [ "$rc" = 0 ] && [ "$got" = "$2" ] || { bad "$(basename "$1"): generalized order ($got), expected ($2) (exit $rc)"; grep -E "^(generalized|  generalized|claims|problems|result)" "$T/out" | head -6; }
}

order "$D/wh_dkd_corrector_3.lua" 4,2
order "$D/wh_dkd_corrector_5.lua" 6,2
order "$D/wh_kdk_corrector_5.lua" 6,2
order "$D/wh_dkd_corrector_11.lua" 12,2
order "$D/wh_kdk_corrector_11.lua" 12,2

# controls: the kernel without corrector; the corrector of the other kernel
sed -e '/^  corrector = {/,/^  },/d' -e 's/generalized_order = { 6, 2 }/generalized_order = { 2, 2 }/' \
  "$D/wh_dkd_corrector_5.lua" > "$T/kernel.lua"
grep -q '^  corrector = ' "$T/kernel.lua" && bad "kernel.lua still has a corrector"
order "$T/kernel.lua" 2,2
{ sed -n '1,/^  corrector = {/p' "$D/wh_dkd_corrector_5.lua"; sed -n '/^  corrector = {/,$p' "$D/wh_kdk_corrector_5.lua" | tail -n +2; } |
  sed 's/generalized_order = { 6, 2 }/generalized_order = { 2, 2 }/' > "$T/swapped.lua"
order "$T/swapped.lua" 2,2

[ $fail = 0 ] && echo "cli_corrector_orders: ok"
exit $fail
