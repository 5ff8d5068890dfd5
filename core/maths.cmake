# Filled in by the maths module.
