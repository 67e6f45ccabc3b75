-- sqrt(t - 1/2) is complex on [0, 1/2): not a real basis function on [0, 1]
return { name = "branch_point", basis = { "1", "sqrt(t - 1/2)" }, nodes = { "1/2", "1" } }
