-- span{t, t^2} at {1/3, 1}: sum b = 1 happens to hold, but row 1 of A does not sum to c_1
return { name = "row_sum_defect", basis = { "t", "t^2" }, nodes = { "1/3", "1" } }
