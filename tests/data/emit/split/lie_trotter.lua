-- The Lie-Trotter splitting of two named flows: a for h, then b for h.
-- Order 1; its first and last substeps are of different flows, so that one
-- step ends where the next begins with nothing to merge.
return {
  name = "lie_trotter",
  order = 1,
  flows = { "a", "b" },
  splitting = { { "a", "1" }, { "b", "1" } },
}
