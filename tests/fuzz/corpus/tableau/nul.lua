return { name = "t", s = 1, c = {"1\0junk"}, A = {{"1/2"}}, b = {"1"} }
