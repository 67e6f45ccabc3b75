-- log(t) is singular at t = 0: rigorous integration cannot converge
return { name = "log_singular", basis = { "1", "log(t)" }, nodes = { "1/2", "1" } }
