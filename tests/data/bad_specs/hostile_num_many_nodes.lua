-- 100,000 nodes: FLINT used to abort allocating the s x s matrices.  vigen
-- refuses more than 256 stages (exit 2).
local n = {}
for i = 1, 100000 do n[i] = tostring(i) .. "/100001" end
return { name = "hostile_num_many_nodes", nodes = n, basis = "lagrange" }
