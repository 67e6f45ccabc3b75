-- Not a method: entries chosen to test correct rounding of literals.
-- 1/3 = 0x1.5555...p-2 rounds down in every format; 1/10 = 0x1.9999...p-4
-- rounds up to 0x1.999999999999ap-4 in double.
return {
  name = "rounding", s = 2,
  c = { "1/3", "1/10" },
  A = { { "1/3", "0" }, { "1/10", "0" } },
  b = { "1/2", "1/2" },
}
