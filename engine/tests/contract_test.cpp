// A contract string reads as docs/design.md defines it, writes back the same, and every malformed one is
// refused naming its key.
#include <rast/contract.h>
#include <rast/engine.h>

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace rast {
namespace {

// The message parse throws for `text`, or "" if it reads.
std::string refusal(const std::string& text) {
    try {
        Contract::parse(text);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

TEST(Contract, ReadsEveryKey) {
    const Contract c = Contract::parse("name=mine samples=4,1 snap=8 rounding=floor ties=none depth=none");
    EXPECT_EQ(c.name, "mine");
    EXPECT_EQ(c.samples, (std::vector<int>{1, 4}));
    EXPECT_EQ(c.snap, 8);
    EXPECT_EQ(c.rounding, Contract::Rounding::floor);
    EXPECT_FALSE(c.top_left);
    EXPECT_FALSE(c.zid);
    EXPECT_TRUE(c.renders(4));
    EXPECT_FALSE(c.renders(8));
    EXPECT_TRUE(c.deterministic());
    EXPECT_FALSE(Contract::parse("name=a samples=1 snap=0 rounding=any ties=top-left depth=zid").deterministic());
}

TEST(Contract, KeysInAnyOrderAndExtraSpaces) {
    const Contract c = Contract::parse("  depth=zid ties=top-left   snap=none samples=16 name=x.y-z_1+  ");
    EXPECT_EQ(c.text(), "name=x.y-z_1+ samples=16 snap=none ties=top-left depth=zid");
}

TEST(Contract, TextReadsBack) {
    for (const char* text : {"name=a samples=1,4,8,16 snap=24 rounding=any ties=none depth=zid",
                             "name=b samples=8 snap=none ties=top-left depth=none",
                             "name=c samples=1,16 snap=0 rounding=nearest-even ties=top-left depth=zid"}) {
        EXPECT_EQ(Contract::parse(text).text(), text);
        EXPECT_EQ(Contract::parse(Contract::parse(text).text()), Contract::parse(text));
    }
}

TEST(Contract, RefusesEachMalformedKeyByName) {
    const std::string ok = " samples=1 snap=none ties=top-left depth=zid";
    EXPECT_EQ(refusal("samples=1 snap=none ties=top-left depth=zid"), "contract key 'name': missing");
    EXPECT_EQ(refusal("name=a snap=none ties=top-left depth=zid"), "contract key 'samples': missing");
    EXPECT_EQ(refusal("name=a" + ok + " colour=red"),
              "contract key 'colour': unknown (known: name, samples, snap, rounding, ties, depth)");
    EXPECT_EQ(refusal("name=a name=b" + ok), "contract key 'name': given twice");
    EXPECT_EQ(refusal("name=a" + ok + " fast"), "contract word 'fast' is not key=value");
    EXPECT_EQ(refusal("name=a b" + ok), "contract word 'b' is not key=value");
    EXPECT_EQ(refusal("name=" + ok),
              "contract key 'name': '' is not a word of at most 64 letters, digits, '_', '-', '.' or '+'");
    EXPECT_EQ(refusal("name=a samples=2 snap=none ties=top-left depth=zid"),
              "contract key 'samples': '2' is not 1, 4, 8 or 16");
    EXPECT_EQ(refusal("name=a samples=1,,4 snap=none ties=top-left depth=zid"),
              "contract key 'samples': '' is not an integer in 1..16");
    EXPECT_EQ(refusal("name=a samples=4,4 snap=none ties=top-left depth=zid"), "contract key 'samples': 4 twice");
    EXPECT_EQ(refusal("name=a samples=1 snap=25 rounding=floor ties=top-left depth=zid"),
              "contract key 'snap': '25' is not an integer in 0..24");
    EXPECT_EQ(refusal("name=a samples=1 snap=8 ties=top-left depth=zid"),
              "contract key 'rounding': missing (snap=8 needs it)");
    EXPECT_EQ(refusal("name=a samples=1 snap=none rounding=floor ties=top-left depth=zid"),
              "contract key 'rounding': applies only with snap=N");
    EXPECT_EQ(refusal("name=a samples=1 snap=8 rounding=up ties=top-left depth=zid"),
              "contract key 'rounding': 'up' is not nearest-even, floor or any");
    EXPECT_EQ(refusal("name=a samples=1 snap=none ties=bottom-right depth=zid"),
              "contract key 'ties': 'bottom-right' is not top-left or none");
    EXPECT_EQ(refusal("name=a samples=1 snap=none ties=none depth=z"), "contract key 'depth': 'z' is not zid or none");
    EXPECT_EQ(refusal(""), "contract key 'name': missing");
}

TEST(Contract, RastsOwnEnginesPromiseWhatTheyKeep) {
    EXPECT_EQ(reference_engine().contract->text(), "name=reference samples=1,4,8,16 snap=none ties=top-left depth=zid");
    EXPECT_EQ(fast_contract(fast::Precision::fixed4)->text(),
              "name=fixed4 samples=1,4,8,16 snap=4 rounding=nearest-even ties=top-left depth=zid");
    EXPECT_EQ(fast_contract(fast::Precision::fixed16)->snap, 16);
    EXPECT_EQ(fast_contract(fast::Precision::float32), std::nullopt);
    EXPECT_EQ(fast_contract(fast::Precision::float64), std::nullopt);
}

}  // namespace
}  // namespace rast
