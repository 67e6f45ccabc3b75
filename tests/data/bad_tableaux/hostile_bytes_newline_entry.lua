-- a newline inside an entry that does not parse: the message stays on one line
return { name = "newline entry", s = 1, c = { "1/2" }, A = { { "1/2" } }, b = { "1\n+ junk(" } }
