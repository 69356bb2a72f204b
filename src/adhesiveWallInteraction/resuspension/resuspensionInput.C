// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "resuspensionInput.H"
#include "wallInteractionEntry.H"

namespace
{

using Model = brachDunn::DepositResuspension;

//- The resuspension's type (rollingBalance or rockNRoll), set in model
Foam::word readKind(const Foam::dictionary& sub, Model& model)
{
    using namespace Foam;
    const word type
    (
        checkedInput::readWord
        (
            sub, "type", word::null, {"rollingBalance", "rockNRoll"}
        )
    );
    if (type.empty())
    {
        checkedInput::fail
        (
            sub, "type", "missing", "must be rollingBalance or rockNRoll"
        );
    }
    model.kind =
        type == "rollingBalance"
      ? Model::Kind::rollingBalance : Model::Kind::rockNRoll;
    return type;
}


//- w, and seed, rmsRatio and frequencyPlus where given (the keywords of
//  known left to their defaults are noted in settings)
void readNumbers
(
    const Foam::dictionary& sub,
    const Foam::wordList& known,
    const Foam::checkedInput::magnitudes& magnitudes,
    Foam::resuspensionSettings& settings
)
{
    using namespace Foam;
    Model& model = settings.model;
    model.w = checkedInput::readNumber(sub, "w");
    if (!(model.w > 0))
    {
        checkedInput::fail
        (
            sub, "w", checkedInput::entryText(*checkedInput::find(sub, "w")),
            "must be > 0 [J/m^2]"
        );
    }
    magnitudes.check(sub, "w", model.w, brachDunn::magnitude::surfaceEnergy);
    for (const word& keyword : known)
    {
        if
        (
            (keyword == "adhesionSpread" || keyword == "seed"
          || keyword == "rmsRatio" || keyword == "frequencyPlus")
         && !checkedInput::find(sub, keyword)
        )
        {
            settings.defaulted.push_back(keyword);
        }
    }
    settings.seed = checkedInput::readCount(sub, "seed", 1);
    model.rmsRatio =
        checkedInput::readNumber(sub, "rmsRatio", model.rmsRatio);
    model.frequencyPlus =
        checkedInput::readNumber(sub, "frequencyPlus", model.frequencyPlus);
}


//- The adhesionSpread sub-dictionary, where given
void readAdhesionSpread(const Foam::dictionary& sub, Model& model)
{
    using namespace Foam;
    if (!checkedInput::findDictionary(sub, "adhesionSpread", "{ type ...; }"))
    {
        return;
    }
    const dictionary spread
    (
        checkedInput::subDictionary
        (
            sub, "adhesionSpread", "{ type ...; }", "resuspension"
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
        model.spread = Model::Spread::logNormal;
        model.logNormal =
        {
            checkedInput::readNumber(spread, "geometricMean"),
            checkedInput::readNumber(spread, "geometricSpread")
        };
    }
    else
    {
        if (spreadType.empty())
        {
            checkedInput::fail
            (
                spread, "type", "missing",
                "must be none, logNormal or biasi"
            );
        }
        checkedInput::requireKnownKeywords
        (
            spread, {"type"}, "adhesionSpread of type " + spreadType
        );
        model.spread =
            spreadType == "none" ? Model::Spread::none : Model::Spread::biasi;
    }
    if (model.spread == Model::Spread::logNormal)
    {
        checkedInput::coreCall(spread, [&]{ model.logNormal.check(); });
    }
}

} // End anonymous namespace


std::optional<Foam::resuspensionSettings> Foam::readResuspension
(
    const dictionary& dict,
    const std::optional<brachDunn::ElasticMaterial>& wall,
    const std::function<brachDunn::ElasticMaterial()>& particle,
    const checkedInput::magnitudes& magnitudes
)
{
    if (!checkedInput::findDictionary(dict, "resuspension", "{ type ...; ... }"))
    {
        return std::nullopt;
    }
    const dictionary sub
    (
        checkedInput::subDictionary
        (
            dict, "resuspension", "{ type ...; ... }", "resuspension"
        )
    );

    resuspensionSettings settings;
    Model& model = settings.model;
    const word type(readKind(sub, model));

    wordList known{"type", "w", "adhesionSpread", "seed"};
    if (model.kind == Model::Kind::rockNRoll)
    {
        known.append(wordList{"rmsRatio", "frequencyPlus"});
    }
    else if (!wall)
    {
        known.append(wordList{"E", "nu"});
    }
    checkedInput::requireKnownKeywords
    (
        sub, known, "resuspension of type " + type
      + (model.kind == Model::Kind::rollingBalance && wall
        ? std::string(" in an adhesive entry (its E and nu are the wall's)")
        : std::string())
    );

    readNumbers(sub, known, magnitudes, settings);
    readAdhesionSpread(sub, model);

    if (model.kind == Model::Kind::rollingBalance)
    {
        const brachDunn::ElasticMaterial wallMaterial =
            wall ? *wall : readElasticMaterial(sub, magnitudes);
        model.contactModulus = brachDunn::contactModulus(particle(), wallMaterial);
    }
    checkedInput::coreCall(sub, [&]{ model.check(); });
    return settings;
}
