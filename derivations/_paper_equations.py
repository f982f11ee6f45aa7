r"""The paper's numbered equations (1)-(51) as printed, in LaTeX, for the derivation report.

Display only: no derivation asserts against these strings (each derivation types the paper's
form as a SymPy expression to assert against).  The report shows ``EquationCheck.printed`` when
a derivation supplied it, and otherwise the entry here, so that equations no derivation covers
still appear, as printed, in the list of gaps.

Extracted once, by a throw-away script, from the Markdown conversion of the paper
(``paper/asymptotic-partial-slip-2022.md``, which users do not have, hence this committed copy):
every ``$$ ... $$`` display block whose equation number is either a ``\tag{N}`` inside it or a
``(N)`` right after it; ``\tag``, trailing punctuation and line breaks removed.  Hand
corrections of conversion artefacts, nothing else:

* (8), (12), (40): the conversion split these between a display block and running text; the
  pieces (including the range "for b < x < a2") are joined into one display.
* (13): the dashed principal-value integral came out as ``f_{b}^{a_{1}}``; written here as
  ``\mathrm{PV}\!\int_{b}^{a_{1}}`` (and likewise on ``(b, a_2)``).

Printed errors are kept as printed (e.g. the unbalanced bars of (25), ``P_k`` in (47)): the
report's errata section sets them against the derived forms.
"""

from __future__ import annotations

PAPER_EQUATIONS: dict[str, str] = {
    "1": r"q_d(z) = \frac{E^*}{2\pi\sqrt{z}} \int_{\Omega} \frac{\sqrt{r} B_x(r) dr}{r-z}",
    "2": (
        r"\frac{\Delta P}{P - P_1} = \frac{\Delta Q}{Q - Q_1} = \frac{\Delta \sigma}{\sigma -"
        r" \sigma_1}"
    ),
    "3": (
        r"\Delta P = P_2 - P_1, \quad \Delta Q = Q_2 - Q_1, \quad \Delta \sigma = \sigma_2 -"
        r" \sigma_1"
    ),
    "4": r"p_i(x; P_i) = L_{I,i}\sqrt{a_i - x}",
    "5": r"q_i(x; P_i) = L_{II,i} \sqrt{a_i - x}",
    "6": (
        r"\Delta q(x) = L_{II,2} \sqrt{a_2 - x} - L_{II,1} H(a_1 - x) \sqrt{a_1 - x} \quad"
        r" \text{for} \quad x < a_2"
    ),
    "7": (
        r"q_{2}(x) = q_{1}(x) + L_{II,2}\sqrt{a_{2}-x} - L_{II,1}H(a_{1}-x)\sqrt{a_{1}-x} + "
        r"\frac{E^{*}}{2\pi\sqrt{a_{2}-x}}\int_{a_{2}}^{b}\frac{"
        r"\sqrt{a_{2}-t}B_{x}^{1\to2}(a_{2}-t)dt}{t-x}"
    ),
    "8": r"q_2(x) = \mu p_2(x) = \mu L_{I,2} \sqrt{a_2 - x} \quad \text{for} \quad b < x < a_2",
    "9": (
        r"\Delta q(x) = -(L_{II,2}\sqrt{a_2 - x} - L_{II,1}H(a_1 - x)\sqrt{a_1 - x}) \quad"
        r" \text{for} \quad x < a_2"
    ),
    "10": (
        r"q_{1}(x) = q_{2}(x) - (L_{II,2}\sqrt{a_{2} - x} - L_{II,1}H(a_{1} - x)\sqrt{a_{1} -"
        r" x}) + \frac{E^{*}}{2\pi\sqrt{a_{2} - x}} \int_{a_{2}}^{b} \frac{\sqrt{a_{2} -"
        r" t}B_{x}^{2 \to 1}(a_{2} - t)dt}{t - x}"
    ),
    "11": (
        r"q_1(x) = -\mu p_1(x) = -\mu L_{I,1} H(a_1 - x) \sqrt{a_1 - x} \quad \text{for} \quad"
        r" b < x < a_2"
    ),
    "12": (
        r"(\mu L_{I,1} + L_{II,1})H(a_1 - x)\sqrt{a_1 - x} + (\mu L_{I,2} - L_{II,2})\sqrt{a_2"
        r" - x} = \frac{E^*}{2\pi\sqrt{a_2 - x}} \int_{a_2}^{b} \frac{\sqrt{a_2 - t}B_x^{1 \to"
        r" 2}(a_2 - t)dt}{t - x} \quad \text{for} \quad b < x < a_2"
    ),
    "13": (
        r"B_{x}^{1 \to 2}(a_{2} - x) = \frac{2\sqrt{x - b}}{\pi E^{*}} \left[ (\mu L_{I,1} +"
        r" L_{II,1}) \mathrm{PV}\!\int_{b}^{a_{1}} \sqrt{\frac{a_{1} - t}{t - b}} \frac{dt}{t"
        r" - x} + (\mu L_{I,2} - L_{II,2}) \mathrm{PV}\!\int_{b}^{a_{2}} \sqrt{\frac{a_{2} -"
        r" t}{t - b}} \frac{dt}{t - x} \right]"
    ),
    "14": (
        r"\int_{\beta}^{1} \sqrt{\frac{1-t}{t-\beta}} \frac{\mathrm{d}t}{t-x} = \begin{cases}"
        r" -\pi & \text{for } \beta < x < 1, \\ -\pi \left(1 -"
        r" \sqrt{\frac{x-1}{x-\beta}}\right) & \text{for } x > 1, \end{cases}"
    ),
    "15": (
        r"B_x^{1 \to 2}(a_2 - x) = -\frac{2\sqrt{x - b}}{E^*} \left( \mu(L_{I,1} + L_{I,2}) +"
        r" L_{II,1} - L_{II,2} \right) + \frac{2(\mu L_{I,1} + L_{II,1})}{E^*} H(x -"
        r" a_1)\sqrt{x - a_1}"
    ),
    "16": (
        r"0 = (\mu L_{I,1} + L_{II,1}) \int_{b}^{a_{1}} \sqrt{\frac{a_{1} - t}{t - b}} \,"
        r" \mathrm{d}t + (\mu L_{I,2} - L_{II,2}) \int_{b}^{a_{2}} \sqrt{\frac{a_{2} - t}{t -"
        r" b}} \, \mathrm{d}t"
    ),
    "17": (
        r"b = \frac{(\mu L_{I,2} - L_{II,2}) a_2 + (\mu L_{I,1} + L_{II,1}) a_1}{(\mu L_{I,2}"
        r" - L_{II,2}) + (\mu L_{I,1} + L_{II,1})}"
    ),
    "18": (
        r"\lambda = \frac{\Delta Q}{\Delta P} = \frac{Q - Q_1}{P - P_1}, \quad \eta ="
        r" \frac{\Delta \sigma}{\Delta P} = \frac{\sigma - \sigma_1}{P - P_1}"
    ),
    "19": r"L_I = \frac{1}{\pi} \sqrt{\frac{2}{a}} \frac{\mathrm{d}P}{\mathrm{d}a}",
    "20": (
        r"L_{II} = \frac{1}{\pi} \sqrt{\frac{2}{a}} \frac{\mathrm{d}Q}{\mathrm{d}a} +"
        r" \frac{1}{4} \sqrt{2a} \frac{\mathrm{d}\sigma}{\mathrm{d}a}"
    ),
    "21": (
        r"L_{II} = \frac{1}{\pi} \sqrt{\frac{2}{a}} \left(\lambda + \frac{\pi \eta"
        r" a}{4}\right) \frac{\mathrm{d}P}{\mathrm{d}a} = \left(\lambda + \frac{\pi \eta"
        r" a}{4}\right) L_I"
    ),
    "22": (
        r"b = \frac{\left(1 - \frac{\lambda}{\mu} - \frac{\pi a_2}{4} \frac{\eta}{\mu}\right)"
        r" L_{I,2} a_2 + \left(1 + \frac{\lambda}{\mu} + \frac{\pi a_1}{4}"
        r" \frac{\eta}{\mu}\right) L_{I,1} a_1}{\left(1 - \frac{\lambda}{\mu} - \frac{\pi"
        r" a_2}{4} \frac{\eta}{\mu}\right) L_{I,2} + \left(1 + \frac{\lambda}{\mu} + \frac{\pi"
        r" a_1}{4} \frac{\eta}{\mu}\right) L_{I,1}}"
    ),
    "23": r"a_2 = a(P_2) = a(P_1 + \Delta P) = a_1 + \Delta P a'(\xi)",
    "24": r"\frac{\Delta P a'(P)}{a_1} \ll 1",
    "25": (
        r"\frac{b-a_1}{a_1} = \frac{a_2 - a_1}{a_1} \left| 1 + \frac{\left(1 +"
        r" \frac{\lambda}{\mu} + \frac{\pi a_1}{4} \frac{\eta}{\mu}\right) L_{I,1}}{\left(1 -"
        r" \frac{\lambda}{\mu} - \frac{\pi a_2}{4} \frac{\eta}{\mu}\right) L_{I,2}}"
        r" \right|^{-1} \right| \ll 1"
    ),
    "26": r"\frac{\Delta P L_I'(P)}{L_{I,1}} \ll 1",
    "27": (
        r"\frac{\Delta Pa'(P)}{a_1} \left| 1 - \frac{\lambda}{\mu} - \frac{\pi \eta a_1}{4\mu}"
        r" \right| \ll 1"
    ),
    "28": (
        r"\frac{b}{a_1} \approx 1 - \frac{\Delta P a'(P_1)}{2a_1} \left(\frac{\lambda}{\mu} +"
        r" \frac{\pi a_1}{4}\frac{\eta}{\mu} - 1\right)"
    ),
    "29": r"a^2 = \frac{4PR}{\pi E^*}",
    "30": r"\frac{\Delta P}{P_1} \ll 1",
    "31": r"L_{I} = \frac{E^{*}}{R} \sqrt{\frac{a}{2}} = \frac{2P}{\pi} \sqrt{\frac{2}{a^{3}}}",
    "32": (
        r"\frac{\Delta P}{P_1} \ll 1, \quad \frac{\Delta P}{P_1} \left| 1 -"
        r" \frac{\lambda}{\mu} \right| \ll 1"
    ),
    "33": r"P_K = \frac{P_1 + P_2}{2} - \frac{Q_2 - Q_1}{2\mu}",
    "34": (
        r"b^{2} = \frac{2R}{\pi E^{*}} \left( P_{1} + P_{2} - \frac{Q_{2} - Q_{1}}{\mu}"
        r" \right)"
    ),
    "35": r"b^{2} = a_{1}^{2} \left( 1 + \frac{\Delta P}{2\mu P_{1}} (\mu - \lambda) \right)",
    "36": (
        r"\frac{b}{a_1} \approx 1 - \left(\frac{\lambda}{\mu} - 1\right) \frac{1}{4}"
        r" \frac{\Delta P}{P_1}"
    ),
    "37": r"q(x) = \frac{K_{II}}{\sqrt{a-x}} \quad \text{as} \quad a-x \to 0",
    "38": r"K_{II} = \frac{Q}{\pi\sqrt{2a}} + \frac{\sigma}{4}\sqrt{\frac{a}{2}}",
    "39": (
        r"\frac{\Delta K_{II}}{\Delta P} = \frac{\lambda}{\pi\sqrt{2a}} +"
        r" \frac{\eta}{4}\sqrt{\frac{a}{2}}"
    ),
    "40": (
        r"b = a_1 - d_1, \quad \text{where} \quad d_1 = \frac{\Delta K_{II}}{\mu L_I} -"
        r" \frac{\Delta a}{2}"
    ),
    "41": (
        r"b = a_1 - \frac{\Delta PR}{\pi\mu E^* a_1} \left(\lambda + \frac{\pi\eta"
        r" a_1}{4}\right) + \frac{a_2 - a_1}{2}"
    ),
    "42": (
        r"a_2 = a(P_1 + \Delta P) \approx a_1 \left( 1 + \frac{2R\Delta P}{\pi E^* a_1^2}"
        r" \right)"
    ),
    "43": (
        r"b \approx \frac{a_1}{2} \left( 2 + \frac{2R\Delta P}{\pi E^* a_1^2} \right) -"
        r" \frac{\Delta PR}{\pi a_1 \mu E^*} \left( \lambda + \frac{\pi \eta a_1}{4} \right)"
    ),
    "44": (
        r"\frac{b}{a_1} \approx 1 - \left(\frac{\lambda}{\mu} + \frac{\eta}{\mu} \frac{\pi"
        r" a_1}{4} - 1\right) \frac{\Delta P}{4P_1}"
    ),
    "45": r"\frac{b}{a_1} \approx 1 - \left(\frac{\lambda}{\mu} - 1\right) \frac{\Delta P}{4P_1}",
    "46": r"q_{\rm diff}(x) = q_2(x) - q_1(x)",
    "47": (
        r"q_{\rm diff}(x) = \begin{cases} \mu(p(x, P_2) + p(x, P_1) - 2p(x, P_k)) & \text{for"
        r" } 0 < x < b \\ \mu(p(x, P_2) + p(x, P_1)) & \text{for } b < x < a_1, \\ \mu p(x,"
        r" P_2) & \text{for } a_1 < x < a_2 \end{cases}"
    ),
    "48": r"p(x,P) = \frac{2P}{\pi a^2} \sqrt{a^2 - x^2}",
    "49": (
        r"q_{\rm diff}(x) = L_{II,2}\sqrt{a_2 - x} - L_{II,1}H(a_1 - x)\sqrt{a_1 - x} +"
        r" \frac{E^*}{2\pi\sqrt{a_2 - x}} \int_{a_2}^{b} \frac{\sqrt{a_2 - t}B_x^{1 \to 2}(a_2"
        r" - t)dt}{t - x}"
    ),
    "50": (
        r"b = \frac{\left(1 - \frac{\lambda}{\mu} - \frac{\pi a_2}{4} \frac{\eta}{\mu}\right)"
        r" L_{I,2} a_2 + \left(1 + \frac{\lambda}{\mu} + \frac{\pi a_1}{4}"
        r" \frac{\eta}{\mu}\right) L_{I,1} a_1}{\left(1 - \frac{\lambda}{\mu} - \frac{\pi"
        r" a_2}{4} \frac{\eta}{\mu}\right) L_{I,2} + \left(1 + \frac{\lambda}{\mu} + \frac{\pi"
        r" a_1}{4} \frac{\eta}{\mu}\right) L_{I,1}}"
    ),
    "51": (
        r"\frac{b}{a_1} \approx 1 - \frac{\Delta Pa'(P_1)}{2a_1} \left(\frac{\lambda}{\mu} +"
        r" \frac{\pi a_1}{4}\frac{\eta}{\mu} - 1\right)"
    ),
}
