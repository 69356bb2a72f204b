# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""The size limits' measure (tests/limits/limits.py) on small sources whose
functions and lengths are counted by hand."""
import importlib.util
import pathlib
import textwrap

SPEC = importlib.util.spec_from_file_location(
    "limits", pathlib.Path(__file__).resolve().parents[1] / "limits" / "limits.py"
)
limits = importlib.util.module_from_spec(SPEC)
SPEC.loader.exec_module(limits)

CXX = textwrap.dedent('''\
    // a comment with a brace {
    #include "x.H"
    namespace Foam
    {
    /* a block comment { } */
    template<class CloudType>
    Foam::Model<CloudType>::Model
    (
        const dictionary& dict
    )
    :
        Base(dict, {"a", "b"}),
        value_(read(dict))
    {
        const auto f = [&](int i) { return i; };
        if (true) { f(1); }
        const char* s = "}";
    }

    class Inner : public Base
    {
        int size() const override
        {
            return 1;
        }
        int n_ = 0;
    };

    int Foam::free(int x)
    {
        return x;
    }
    }
    ''')


def test_cxx_functions_and_their_lines():
    found = limits.cxx_functions(CXX)
    assert found == [
        ("Foam::Model<CloudType>::Model", 6, 18),
        ("size", 22, 25),
        ("Foam::free", 29, 32),
    ]


def test_python_functions_and_their_lines():
    source = "def f():\n    return 1\n\n\nclass A:\n    @staticmethod\n    def g():\n        pass\n"
    assert limits.python_functions(source) == [("f", 1, 2), ("g", 6, 8)]


def test_over_the_limits_and_the_list(tmp_path, capsys):
    src = tmp_path / "src" / "x"
    src.mkdir(parents=True)
    body = "\n".join("    x += %d;" % i for i in range(70))
    (src / "long.C").write_text("int f(int x)\n{\n%s\n    return x;\n}\n" % body)
    # 4 lines and 600 empty ones
    (src / "short.C").write_text("int g()\n{\n    return 0;\n}\n" + "\n" * 600)
    over = limits.measure(tmp_path)
    assert over == {"src/x/long.C:f": 74, "src/x/short.C": 604}
    known = tmp_path / "known.txt"
    known.write_text("74 src/x/long.C:f\n604 src/x/short.C\n")
    assert limits.main([str(tmp_path), "--known", str(known)]) == 0
    known.write_text("73 src/x/long.C:f\n604 src/x/short.C\n1 src/x/gone.C\n")
    assert limits.main([str(tmp_path), "--known", str(known)]) == 1
    err = capsys.readouterr().err
    assert "grew: src/x/long.C:f" in err and "take it off" in err
