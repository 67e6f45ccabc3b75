return { name = "t", s = 100000 }
