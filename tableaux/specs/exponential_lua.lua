-- A basis built programmatically: Lua functions receive the time t as an arb
-- ball and must return a ball.  Write exact constants as strings (exact("1/3"))
-- or with integer arithmetic on balls (t/3); a Lua float such as 1/3 is refused.
local function shifted_exp(k)
  return function(t) return exp(k * t) - 1 end
end
return {
  name = "exponential_lua",
  description = "psi = {1, exp(t) - 1, exp(2t) - 1} at the 3 Gauss-Legendre nodes, built with Lua functions",
  source = "vigen example of a programmatic basis",
  basis = { "1", shifted_exp(1), shifted_exp(2) },
  nodes = gauss_legendre(3),
}
