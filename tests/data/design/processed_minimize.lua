-- The best kernel with three kicks of effective order 4 for separable H and
-- its corrector: three kicks leave one step free (processed.lua holds it),
-- and minimize moves it to the smallest separable error constant of the
-- processed step C K C^-1 that the checker reports.  At 3 forces per step
-- (the kernel's; C and C^-1 run once, at the start and at each output) it
-- has a separable constant 0.0192 against Forest-Ruth's 0.182 (docs/design.md).
return { name = "pm", design = "processed", kernel = "splitting", stages = 3, order = 4, symmetric = true,
         minimize = "error_constant_separable", starts = 3 }
