// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "checkedInput.H"

#include <algorithm>
#include <cstdlib>
#include <fstream>

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * //

void Foam::checkedInput::recordKeywords
(
    const wordList& valid,
    const std::string& what
)
{
    const char* path = std::getenv("ADHESIVE_WALL_KEYWORDS");
    if (!path || !*path)
    {
        return;
    }
    std::ofstream out(path, std::ios::app);
    for (const word& keyword : valid)
    {
        out << keyword << '\t' << what << '\n';
    }
}


void Foam::checkedInput::requireKnownKeywords
(
    const dictionary& dict,
    const wordList& valid,
    const std::string& what
)
{
    recordKeywords(valid, what);
    for (const entry& e : dict)
    {
        if (std::find(valid.begin(), valid.end(), e.keyword()) == valid.end())
        {
            std::string names;
            for (const word& keyword : valid)
            {
                names += ' ' + keyword;
            }
            fail
            (
                dict, e.keyword(), entryText(e),
                "not a keyword of " + what + "; valid keywords:" + names
            );
        }
    }
}


// ************************************************************************* //
