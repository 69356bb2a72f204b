// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// compat::cloudFunctionHooks against base classes that declare the cloud
// function hooks in each form OpenCFD's releases have (mocks of the
// declarations, read in OpenCFD's public CloudFunctionObject.H: v1912; the
// 2020 change, whose evolve hooks take the tracking data; the later one,
// whose postMove takes the tracking data and returns whether the parcel is
// kept). Each base is driven as that release's CloudFunctionObjectList
// drives it; the hooks must reach beforeEvolve and afterMove, and the
// parcel removed by afterMove must be removed. Built and run by
// tests/compile/hookForms; with -DWRONG_FORM the v1912 form is forced onto
// the latest base, which must not compile ('override' on hooks the base
// does not declare).

#include "cloudFunctionHooks.H"

#include <cstdlib>
#include <iostream>

using Foam::point;
using Foam::scalar;
using Foam::compat::cloudFunctionHooks;
using Foam::compat::hookForm;

namespace mock
{

// OpenFOAM's tracking data converts implicitly from any cloud (a template
// constructor): the form's detection must not be fooled by it
struct trackingData
{
    bool keepParticle = true;
    trackingData() = default;
    template<class Cloud>
    trackingData(const Cloud&)
    {}
};

struct parcel
{
    typedef mock::trackingData trackingData;
    int moves = 0;
};

struct cloud
{
    typedef mock::parcel parcelType;
};

struct base
{
    explicit base(int)
    {}
    virtual ~base() = default;
};

// v1912
struct v1912 : base
{
    using base::base;
    virtual void preEvolve()
    {}
    virtual void postMove(parcel&, const scalar, const point&, bool&)
    {}
};

// OpenCFD's 2020 change
struct trackingDataEvolve : base
{
    using base::base;
    virtual void preEvolve(const trackingData&)
    {}
    virtual void postMove(parcel&, const scalar, const point&, bool&)
    {}
};

// The later form
struct keepReturned : base
{
    using base::base;
    virtual void preEvolve(const trackingData&)
    {}
    virtual bool postMove
    (
        parcel&, const scalar, const point&, const trackingData&
    )
    {
        return true;
    }
};

} // End namespace mock


// A cloud function of the project's: counts the calls, removes the parcel
template<class Base, hookForm Form = Foam::compat::formOf
<
    Base, mock::parcel, mock::trackingData
>()>
struct function : cloudFunctionHooks<mock::cloud, Base, Form>
{
    using cloudFunctionHooks<mock::cloud, Base, Form>::cloudFunctionHooks;
    int evolves = 0;
    void beforeEvolve() override
    {
        ++evolves;
    }
    void afterMove(mock::parcel& p, const scalar, const point&, bool& keep)
        override
    {
        ++p.moves;
        keep = false;
    }
};

static_assert
(
    Foam::compat::formOf<mock::v1912, mock::parcel, mock::trackingData>()
 == hookForm::v1912
);
static_assert
(
    Foam::compat::formOf
    <
        mock::trackingDataEvolve, mock::parcel, mock::trackingData
    >()
 == hookForm::trackingDataEvolve
);
static_assert
(
    Foam::compat::formOf<mock::keepReturned, mock::parcel, mock::trackingData>()
 == hookForm::keepReturned
);

#ifdef WRONG_FORM
template struct function<mock::keepReturned, hookForm::v1912>;
#endif

static int failures = 0;

static void expect(const bool ok, const char* what)
{
    if (!ok)
    {
        std::cerr << "FAILED: " << what << '\n';
        ++failures;
    }
}

int main()
{
    const point position0(0, 0, 0);
    {
        function<mock::v1912> f(0);
        mock::v1912& b = f;
        mock::parcel p;
        bool keep = true;
        b.preEvolve();
        b.postMove(p, 1e-3, position0, keep);
        expect(f.evolves == 1 && p.moves == 1 && !keep, "v1912's hooks");
    }
    {
        function<mock::trackingDataEvolve> f(0);
        mock::trackingDataEvolve& b = f;
        mock::parcel p;
        mock::trackingData td;
        bool keep = true;
        b.preEvolve(td);
        b.postMove(p, 1e-3, position0, keep);
        expect(f.evolves == 1 && p.moves == 1 && !keep, "the 2020 hooks");
    }
    {
        function<mock::keepReturned> f(0);
        mock::keepReturned& b = f;
        mock::parcel p;
        mock::trackingData td;
        b.preEvolve(td);
        const bool keep = b.postMove(p, 1e-3, position0, td);
        expect(f.evolves == 1 && p.moves == 1 && !keep, "the latest hooks");
    }
    std::cout << "hookForms: " << 3 - failures << " passed, " << failures
        << " failed\n";
    return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
