return { name = "\255\254", s = 1, c = {"1/2"}, A = {{"1/2"}}, b = {"1"}, description = "\27]0;title\7" }
