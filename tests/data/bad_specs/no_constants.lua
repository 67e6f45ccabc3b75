-- span{t, t^2} does not contain the constants: sum b != 1 (a warning, not an error)
return { name = "no_constants", basis = { "t", "t^2" }, nodes = { "1/4", "3/4" } }
