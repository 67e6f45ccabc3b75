-- neither a spec nor a tableau: no nodes, basis, s or A
return { name = "x", description = "a table of no method kind" }
