// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "checkedInput.H"
#include "releaseCompat.H"
#include "OStringStream.H"

#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

using namespace Foam;
using checkedInput::isPunctuation;

//- The tokens of a primitive entry; a dictionary is an error
const ITstream& tokensOf
(
    const dictionary& dict,
    const entry& e,
    const char* expected
)
{
    if (e.isDict())
    {
        checkedInput::fail
        (
            dict, e.keyword(), "{ ... }",
            std::string("must be ") + expected + ", not a dictionary"
        );
    }
    return e.stream();
}


//- Where the items of a bracketed list start in tokens, (a b c) or
//  OpenFOAM's sized N(a b c), its last token closing it; -1 when the
//  tokens are not such a list
label itemsStart(const ITstream& tokens)
{
    const label first = checkedInput::listStart(tokens);
    return
        first >= 0
     && tokens.size() >= first + 2
     && isPunctuation(tokens[tokens.size() - 1], token::END_LIST)
      ? first + 1 : -1;
}


//- Whether a list's size prefix, if it has one, counts its n items
bool prefixCounts(const ITstream& tokens, const label n)
{
    return
        checkedInput::listStart(tokens) != 1 || tokens[0].labelToken() == n;
}


//- The entry of a required keyword
const entry& required(const dictionary& dict, const word& keyword)
{
    const entry* e = checkedInput::find(dict, keyword);
    if (!e)
    {
        checkedInput::fail(dict, keyword, "missing", "keyword is required");
    }
    return *e;
}


//- The tokens OpenFOAM reads where a number was meant to be infinite or
//  NaN: inf, -inf (a sign and a word), nan
bool namesNonFinite(const ITstream& tokens)
{
    const label sign =
        tokens.size() == 2
     && (isPunctuation(tokens[0], '-') || isPunctuation(tokens[0], '+'));
    if (tokens.size() != sign + 1 || !tokens[sign].isWord()) return false;
    std::string w(tokens[sign].wordToken());
    std::transform(w.begin(), w.end(), w.begin(), ::tolower);
    return w == "inf" || w == "infinity" || w == "nan";
}


//- The single number of an entry
scalar numberOf(const dictionary& dict, const entry& e)
{
    const ITstream& tokens = tokensOf(dict, e, "a number");
    const std::string text = checkedInput::entryText(e);
    if (namesNonFinite(tokens))
    {
        checkedInput::fail(dict, e.keyword(), text, "must be a finite number");
    }
    if (tokens.size() != 1 || !tokens[0].isNumber())
    {
        checkedInput::fail(dict, e.keyword(), text, "must be one number");
    }
    const scalar value = tokens[0].number();
    if (!std::isfinite(value))
    {
        checkedInput::fail(dict, e.keyword(), text, "must be a finite number");
    }
    return value;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * //

std::string Foam::checkedInput::entryText(const entry& e)
{
    if (e.isDict())
    {
        return "{ ... }";
    }
    OStringStream os;
    const ITstream& tokens = e.stream();
    forAll(tokens, i)
    {
        // Spaced as written: (a b), not ( a b ); -inf, not - inf
        const bool sign =
            i == 1
         && (isPunctuation(tokens[0], '-') || isPunctuation(tokens[0], '+'));
        if
        (
            i && !sign
         && !isPunctuation(tokens[i - 1], token::BEGIN_LIST)
         && !isPunctuation(tokens[i], token::END_LIST)
        )
        {
            os << ' ';
        }
        if (tokens[i].isNumber())
        {
            os << brachDunn::toText(tokens[i].number()).c_str();
        }
        else
        {
            os << tokens[i];
        }
    }
    return os.str();
}


bool Foam::checkedInput::isPunctuation(const token& t, const char c)
{
    return t.isPunctuation() && t.pToken() == c;
}


Foam::label Foam::checkedInput::listStart(const ITstream& tokens)
{
    const label first = tokens.size() && tokens[0].isLabel() ? 1 : 0;
    return
        tokens.size() > first && isPunctuation(tokens[first], token::BEGIN_LIST)
      ? first : -1;
}


const Foam::entry* Foam::checkedInput::find
(
    const dictionary& dict,
    const word& keyword
)
{
    return compat::findEntry(dict, keyword);
}


void Foam::checkedInput::fail
(
    const dictionary& dict,
    const std::string& keyword,
    const std::string& value,
    const std::string& requirement
)
{
    // A keyword given without a value (sphereDrag;) is named alone
    FatalIOErrorInFunction(dict)
        << "In dictionary " << dict.name() << ": keyword '" << keyword.c_str()
        << (value.empty() ? "'" : "' = ") << value.c_str() << ": "
        << requirement.c_str() << nl << exit(FatalIOError);
    std::abort();   // not reached: exit() stops the run or throws
}


std::string Foam::checkedInput::checkMagnitude
(
    const dictionary& dict,
    const std::string& keyword,
    const scalar value,
    const brachDunn::Magnitude& m,
    const bool extreme,
    const std::string& takenBy
)
{
    try
    {
        return brachDunn::checkMagnitude(m, keyword, value, extreme);
    }
    catch (const brachDunn::InputError& err)
    {
        fail
        (
            dict, err.keyword(), err.value(),
            err.requirement() + " (" + takenBy + " takes it as given)"
        );
    }
}


Foam::scalar Foam::checkedInput::readNumber
(
    const dictionary& dict,
    const word& keyword
)
{
    return numberOf(dict, required(dict, keyword));
}


Foam::scalar Foam::checkedInput::readNumber
(
    const dictionary& dict,
    const word& keyword,
    const scalar deflt
)
{
    const entry* e = find(dict, keyword);
    return e ? numberOf(dict, *e) : deflt;
}


Foam::scalarList Foam::checkedInput::readNumbers
(
    const dictionary& dict,
    const word& keyword
)
{
    scalarList values;
    const entry* e = find(dict, keyword);
    if (!e)
    {
        return values;
    }
    const ITstream& tokens = tokensOf(dict, *e, "a list of numbers");
    const label start = itemsStart(tokens);
    bool good = start >= 0;
    for (label i = start; good && i < tokens.size() - 1; ++i)
    {
        good = tokens[i].isNumber() && std::isfinite(tokens[i].number());
        if (good)
        {
            values.append(tokens[i].number());
        }
    }
    if (!good || !prefixCounts(tokens, values.size()))
    {
        fail
        (
            dict, keyword, entryText(*e),
            "must be a list of finite numbers such as (1e-6 2.5e-6)"
        );
    }
    return values;
}


Foam::List<Foam::keyType> Foam::checkedInput::readKeys
(
    const dictionary& dict,
    const word& keyword,
    const std::string& expected
)
{
    const entry* e = find(dict, keyword);
    if (!e)
    {
        return List<keyType>();
    }
    const ITstream& tokens = tokensOf(dict, *e, expected.c_str());
    // (a "b.*" c), checked token by token before OpenFOAM's list reader
    // sees them
    const label start = itemsStart(tokens);
    bool good = start >= 0;
    for (label i = start; good && i < tokens.size() - 1; ++i)
    {
        good = tokens[i].isWord() || tokens[i].isString();
    }
    if (!good || !prefixCounts(tokens, tokens.size() - 1 - start))
    {
        fail(dict, keyword, entryText(*e), "must be " + expected);
    }
    return List<keyType>(e->stream());
}


Foam::label Foam::checkedInput::readCount
(
    const dictionary& dict,
    const word& keyword,
    const label deflt
)
{
    const entry* e = find(dict, keyword);
    if (!e)
    {
        return deflt;
    }
    const scalar value = numberOf(dict, *e);
    if (!(value >= 0 && value == std::floor(value) && value <= labelMax))
    {
        fail
        (
            dict, keyword, entryText(*e),
            "must be a whole number >= 0 (at most " + std::to_string(labelMax)
          + ")"
        );
    }
    return label(value);
}


bool Foam::checkedInput::readSwitch
(
    const dictionary& dict,
    const word& keyword,
    const bool deflt
)
{
    const entry* e = find(dict, keyword);
    if (!e)
    {
        return deflt;
    }
    const ITstream& tokens = tokensOf(dict, *e, "yes or no");
    if (tokens.size() == 1)
    {
        const token& t = tokens[0];
        if (t.isWord())
        {
            const word& w = t.wordToken();
            if (w == "yes" || w == "on" || w == "true") return true;
            if (w == "no" || w == "off" || w == "false") return false;
        }
        else if (t.isNumber() && (t.number() == 0 || t.number() == 1))
        {
            return t.number() == 1;
        }
    }
    fail
    (
        dict, keyword, entryText(*e),
        "must be yes or no (also on/off, true/false, 1/0)"
    );
}


Foam::word Foam::checkedInput::readWord
(
    const dictionary& dict,
    const word& keyword
)
{
    const entry& e = required(dict, keyword);
    const ITstream& tokens = tokensOf(dict, e, "a word");
    if (tokens.size() != 1 || !tokens[0].isWord())
    {
        fail(dict, keyword, entryText(e), "must be one word");
    }
    return tokens[0].wordToken();
}


Foam::word Foam::checkedInput::readWord
(
    const dictionary& dict,
    const word& keyword,
    const word& deflt,
    const wordList& valid
)
{
    if (!find(dict, keyword))
    {
        return deflt;
    }
    const word value(readWord(dict, keyword));
    if (std::find(valid.begin(), valid.end(), value) == valid.end())
    {
        std::string names;
        for (const word& name : valid)
        {
            names += (names.empty() ? "" : ", ") + name;
        }
        fail(dict, keyword, value, "valid values are " + names);
    }
    return value;
}


const Foam::dictionary* Foam::checkedInput::findDictionary
(
    const dictionary& dict,
    const word& keyword,
    const char* form
)
{
    const entry* found = find(dict, keyword);
    if (found && !found->isDict())
    {
        fail
        (
            dict, keyword, entryText(*found),
            "must be a dictionary, " + keyword + ' ' + form
        );
    }
    return found ? &found->dict() : nullptr;
}


Foam::dictionary Foam::checkedInput::subDictionary
(
    const dictionary& dict,
    const word& keyword,
    const char* form,
    const char* neededBy
)
{
    const dictionary* found = findDictionary(dict, keyword, form);
    if (!found)
    {
        fail
        (
            dict, keyword, "missing",
            std::string(neededBy) + " needs " + keyword + ' ' + form
        );
    }
    dictionary sub(*found);
    sub.name() = dict.name() + "." + keyword;
    return sub;
}


const Foam::dictionary& Foam::checkedInput::baseKeywordsChecked
(
    const dictionary& subModels,
    const word& type,
    const wordList& baseKeywords
)
{
    const dictionary* coeffs =
        findDictionary(subModels, type + "Coeffs", "{ ... }");
    if (!coeffs)
    {
        return subModels;
    }
    for (const word& keyword : baseKeywords)
    {
        if (!find(*coeffs, keyword))
        {
            continue;
        }
        if (keyword == "U")
        {
            readWord(*coeffs, keyword);
        }
        else if (keyword == "UrMax")
        {
            readNumber(*coeffs, keyword);
        }
        else if (keyword == "writePrecision")
        {
            readCount(*coeffs, keyword, 0);
        }
        else
        {
            readSwitch(*coeffs, keyword, false);
        }
    }
    return subModels;
}
