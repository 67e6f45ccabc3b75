-- b[1] hides "junk" behind a NUL byte: refused, not read as "1"
return { name = "nul entry", s = 1, c = { "1/2" }, A = { { "1/2" } }, b = { "1\0junk" } }
