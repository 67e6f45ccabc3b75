-- Strang splitting of two named flows, written with a zero substep and two
-- consecutive substeps of one flow, for the emitter's merging: the method is
-- a/2, b, a/2 (a = "axis1", b = "axis3").
return {
  name = "rotations_strang",
  order = 2,
  flows = { "axis1", "axis3" },
  splitting = { { "axis1", "1/4" }, { "axis1", "1/4" }, { "axis3", "0" }, { "axis3", "1" }, { "axis1", "1/2" } },
}
