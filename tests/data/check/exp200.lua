-- A non-symplectic method whose defect, exp(-200) ~ 2^-288, no literal reveals:
-- b_1 at_11 + b_1 a_11 - b_1^2 = exp(-200).  Exact data is confirmed at >= 1024 bits.
return { name = "exp200", s = 1, symplectic = true, c = { "1" }, A = { { "1" } }, b = { "1" },
         At = { { "exp(-200)" } }, ct = { "exp(-200)" } }
