-- terminal escape sequences in an entry that does not parse: echoed escaped
return { name = "escape entry", s = 1, c = { "1/2" }, A = { { "1/2" } }, b = { "\27[2J\27]0;pwned\7" } }
