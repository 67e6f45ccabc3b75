-- Test data: a first-order splitting corrected by the flow of the bracket
-- {a, b} (one bracket: its sign depends on the convention, here {F, G} =
-- F_q G_p - F_p G_q).  log(exp(h A) exp(h B)) = h (A + B) + (h^2/2) [A, B]
-- + O(h^3) and the flow of {a, b} is -[A, B] in the letters, so that
-- a for h, b for h, {a, b} for h^2/2 is of order 2 (tests/unit/
-- test_emit_brackets.c checks it on the harmonic oscillator, whose {a, b}
-- = -p q has the flow q e^-t, p e^t).
return {
  name = "bracket_ab",
  flows = { "a", "b", "ab" },
  brackets = { ab = { "a", "b" } },
  splitting = {
    { "a", "1" },
    { "b", "1" },
    { "ab", "1/2" },
  },
}
