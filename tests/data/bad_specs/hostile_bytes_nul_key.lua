-- a field "name\0x" is not the field "name": warned about as unknown
return { name = "nul key", ["name\0x"] = "other", nodes = { "0", "1" }, basis = "lagrange" }
