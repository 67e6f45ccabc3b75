-- A node whose decimal exponent overflows every machine integer: FLINT used
-- to abort (SIGABRT) on it.  vigen refuses it as out of range (exit 2).
return { name = "hostile_num_exponent", nodes = { "0", "1e99999999999999999999" }, basis = "lagrange" }
