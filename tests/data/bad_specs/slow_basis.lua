-- each call stays under the per-call cap, but the integrator calls it many times
local function slow(t)
  local x = 0
  for i = 1, 10000 do x = x + i end
  return 1 / (t * t + exact("1/100"))
end
return { name = "slow_basis", basis = { "1", slow }, nodes = { "0", "1" } }
