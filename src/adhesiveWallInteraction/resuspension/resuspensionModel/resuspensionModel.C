// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "resuspensionModel.H"

#include <algorithm>

namespace Foam
{
    defineTypeNameAndDebug(resuspensionModel, 0);
    defineRunTimeSelectionTable(resuspensionModel, dictionary);
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::wordList Foam::resuspensionModel::types()
{
    // rollingBalance first, as the guide names them
    wordList names(dictionaryConstructorTablePtr_->sortedToc());
    std::reverse(names.begin(), names.end());
    return names;
}


Foam::autoPtr<Foam::resuspensionModel> Foam::resuspensionModel::New
(
    const word& type,
    const input& in,
    std::uint64_t& seed,
    std::vector<std::string>& defaulted
)
{
    auto cstrIter = dictionaryConstructorTablePtr_->cfind(type);
    if (!cstrIter.found())
    {
        FatalErrorInFunction
            << "Unknown resuspension type " << type << "; valid types are "
            << types() << exit(FatalError);
    }
    autoPtr<resuspensionModel> model(cstrIter()(in));
    model->read(in, seed, defaulted);
    return model;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::resuspensionModel::read
(
    const input& in,
    std::uint64_t& seed,
    std::vector<std::string>& defaulted
)
{
    const dictionary& dict = in.dict;
    wordList known{"type", "w", "adhesionSpread", "seed"};
    known.append(keywords(in));
    checkedInput::requireKnownKeywords
    (
        dict, known,
        "resuspension of type " + type() + keywordNote(in)
    );

    law_.w = checkedInput::readNumber(dict, "w");
    if (!(law_.w > 0))
    {
        checkedInput::fail
        (
            dict, "w", checkedInput::entryText(*checkedInput::find(dict, "w")),
            "must be > 0 [J/m^2]"
        );
    }
    in.magnitudes.check(dict, "w", law_.w, brachDunn::magnitude::surfaceEnergy);
    for (const word& keyword : known)
    {
        if
        (
            (keyword == "adhesionSpread" || keyword == "seed"
          || keyword == "rmsRatio" || keyword == "frequencyPlus")
         && !checkedInput::find(dict, keyword)
        )
        {
            defaulted.push_back(keyword);
        }
    }
    seed = checkedInput::readCount(dict, "seed", 1);
    readOwn(in);
    readAdhesionSpread(dict);
    checkedInput::coreCall(dict, [&]{ law_.check(); });
}


void Foam::resuspensionModel::readAdhesionSpread(const dictionary& dict)
{
    using Spread = brachDunn::DepositResuspension::Spread;
    if (!checkedInput::findDictionary(dict, "adhesionSpread", "{ type ...; }"))
    {
        return;
    }
    const dictionary spread
    (
        checkedInput::subDictionary
        (
            dict, "adhesionSpread", "{ type ...; }", "resuspension"
        )
    );
    const word spreadType
    (
        checkedInput::readWord
        (
            spread, "type", word::null, {"none", "logNormal", "biasi"}
        )
    );
    if (spreadType == "logNormal")
    {
        checkedInput::requireKnownKeywords
        (
            spread, {"type", "geometricMean", "geometricSpread"},
            "adhesionSpread of type logNormal"
        );
        law_.spread = Spread::logNormal;
        law_.logNormal =
        {
            checkedInput::readNumber(spread, "geometricMean"),
            checkedInput::readNumber(spread, "geometricSpread")
        };
        checkedInput::coreCall(spread, [&]{ law_.logNormal.check(); });
        return;
    }
    if (spreadType.empty())
    {
        checkedInput::fail
        (
            spread, "type", "missing", "must be none, logNormal or biasi"
        );
    }
    checkedInput::requireKnownKeywords
    (
        spread, {"type"}, "adhesionSpread of type " + spreadType
    );
    law_.spread = spreadType == "none" ? Spread::none : Spread::biasi;
}


// ************************************************************************* //
