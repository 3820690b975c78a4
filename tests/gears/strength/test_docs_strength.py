"""Every python block of docs/strength.md runs as written, in order, and the figures it quotes are the program's."""
import contextlib
import doctest
import io
import re
from pathlib import Path

DOC = Path(__file__).parents[3] / "docs" / "strength.md"


def test_code_blocks_run_and_quoted_output_matches():
    text = DOC.read_text(encoding="utf-8")
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    assert len(blocks) >= 5
    env, printed = {}, io.StringIO()
    with contextlib.redirect_stdout(printed):
        for block in blocks:
            if block.lstrip().startswith(">>>"):      # a session: its printed figures are compared as a doctest
                test = doctest.DocTestParser().get_doctest(block, env, "strength.md", str(DOC), 0)
                runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
                runner.run(test, out=printed.write, clear_globs=False)
                assert runner.failures == 0, printed.getvalue()[-2000:]
            else:
                exec(compile(block, str(DOC), "exec"), env)
    out = printed.getvalue()
    quoted = re.search(r"```text\n(.*?)```", text, flags=re.S).group(1)
    assert quoted.strip() in out
    assert "40Cr V 766.9 314.5" in out and "('K_Hbeta',)" in out
    assert "6.393" in out and "6.634" in out and "6.602" in out and "6.582" in out
