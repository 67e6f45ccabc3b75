-- A symmetric kernel with three kicks of effective order 4 for separable H,
-- its first kick held at 3/2 (one condition fewer than order 4 leaves one
-- step free), and its corrector C: the step C K C^-1 has order 4 while the
-- kernel alone has order 2 (Blanes, Casas & Ros, SIAM J. Sci. Comput. 21
-- (1999) 711: a kernel needs 1 condition at h^3, not 2).
return { name = "pk", design = "processed", kernel = "splitting", stages = 3, order = 4, symmetric = true,
         solutions = "all", fix = { b1 = "3/2" } }
