-- sin(pi t) vanishes at both nodes: M = [[1, 1], [0, 0]] is singular
return { name = "singular_m", basis = { "1", "sin(pi*t)" }, nodes = { "0", "1" } }
