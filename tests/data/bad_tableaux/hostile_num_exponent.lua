-- A rounded decimal with an exponent beyond any machine integer (exit 2).
return { name = "hostile_num_exponent", s = 1, c = { "0.5e-99999999999999999999" }, A = { { "1/2" } },
         b = { "1" }, ct = { "1/2" }, At = { { "1/2" } } }
