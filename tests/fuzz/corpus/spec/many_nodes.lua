local t = {} for i = 1, 100000 do t[i] = tostring(i) .. "/100001" end
return { name = "many", nodes = t, basis = "lagrange" }
