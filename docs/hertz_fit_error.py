"""Print the docs/hertz.md table: Brewe–Hamrock fits against the exact Hertz solution."""
from contact import hertz

E_PRIME = float(hertz.effective_modulus(210e9, 0.3))
print("| R_y/R_x | k fit/exact − 1 | K fit/exact − 1 | a fit/exact − 1 | b fit/exact − 1 |")
print("|---:|---:|---:|---:|---:|")
for ratio in (1, 1.5, 2, 3, 5, 10, 20, 23, 30, 40, 60, 100):
    fit = hertz.hertz_contact(5e-3, 5e-3 * ratio, E_PRIME, "fit")
    exact = hertz.hertz_contact(5e-3, 5e-3 * ratio, E_PRIME, "exact")
    (a_f, b_f), (a_x, b_x) = fit.semi_axes(100.0), exact.semi_axes(100.0)
    print(f"| {ratio:g} | {fit.ellipticity / exact.ellipticity - 1:+.2%} | {fit.stiffness / exact.stiffness - 1:+.2%} "
          f"| {a_f / a_x - 1:+.2%} | {b_f / b_x - 1:+.2%} |")
