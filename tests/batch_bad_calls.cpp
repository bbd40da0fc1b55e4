// phong_batch_bad_calls: every shade_batch call whose spans could make it read or write out of
// bounds (a span shorter than N, an output overlapping an input or another output) must reach the
// precondition handler with a message naming the span(s), in every build (NDEBUG included), and
// write nothing. ctest runs it in each preset; .ci/steps/31-release-asan.sh builds it with
// clang++ -O2 -DNDEBUG -fsanitize=address,undefined, where a read or write past a heap buffer is
// a sanitizer report (every buffer here is its own heap allocation of exactly its length).
// Exit 0 when every case passes; prints the failing cases otherwise.
#include <phong/batch.hpp>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace phong;

std::vector<std::string> reported;
void record(const char* message, const char*, int) { reported.emplace_back(message); }

constexpr std::size_t N = 37; // two full steps of 16 lanes and a tail, or more steps of fewer
int failures = 0;

/// A heap buffer of exactly n elements (so ASan sees a read or write one past it), filled with v.
template <class T> std::unique_ptr<T[]> buffer(std::size_t n, T v)
{
    std::unique_ptr<T[]> p(new T[n]);
    for (std::size_t i = 0; i < n; ++i) p[i] = v;
    return p;
}

/// Runs call() with the recording handler; the case passes when exactly one message was reported,
/// it starts with `expect`, and `untouched()` holds afterwards (nothing written).
template <class Call, class Check> void expect_report(const char* name, const std::string& expect, Call call, Check untouched)
{
    reported.clear();
    call();
    const bool one = reported.size() == 1;
    const bool named = one && reported[0].rfind(expect, 0) == 0;
    const bool clean = untouched();
    if (!(one && named && clean)) {
        ++failures;
        std::printf("FAIL %s: %zu reports%s%s, expected \"%s\"; %s\n", name, reported.size(), one ? ": " : "",
                    one ? reported[0].c_str() : "", expect.c_str(), clean ? "nothing written" : "WRITTEN");
    } else {
        std::printf("ok   %s: %s\n", name, reported[0].c_str());
    }
}

template <class T> const light<T> lights1[1] = {light<T>::with_strength({T(1), T(2), T(3), T(1)}, glm::vec<3, T>(T(1)))};
template <class T> std::span<const light<T>> the_lights() { return std::span<const light<T>>(lights1<T>); }

/// Inputs for N points on the heap, each array its own allocation of exactly N.
template <class T> struct inputs {
    std::unique_ptr<T[]> x = buffer<T>(N, T(0.25)), y = buffer<T>(N, T(-0.5)), z = buffer<T>(N, T(-4));
    std::unique_ptr<T[]> nx = buffer<T>(N, T(0)), ny = buffer<T>(N, T(0.5)), nz = buffer<T>(N, T(1));
    soa3<T> positions(std::size_t nx_ = N, std::size_t ny_ = N, std::size_t nz_ = N) const
    {
        return {std::span<const T>(x.get(), nx_), std::span<const T>(y.get(), ny_), std::span<const T>(z.get(), nz_)};
    }
    soa3<T> normals(std::size_t n = N) const
    {
        return {std::span<const T>(nx.get(), n), std::span<const T>(ny.get(), n), std::span<const T>(nz.get(), n)};
    }
};

template <class T> bool all_equal(const T* p, std::size_t n, T v)
{
    for (std::size_t i = 0; i < n; ++i)
        if (std::memcmp(&p[i], &v, sizeof(T)) != 0) return false;
    return true;
}

template <class T> void run(const char* type)
{
    std::printf("-- %s\n", type);
    constexpr features plain{};
    constexpr features with_alpha{.alpha = true};
    constexpr features given = [] {
        features f{};
        f.view = view_model::given;
        return f;
    }();
    const T sentinel = T(-7);
    const inputs<T> in;
    auto r = buffer<T>(N, sentinel), g = buffer<T>(N, sentinel), b = buffer<T>(N, sentinel), a = buffer<T>(N, sentinel);
    const auto out_clean = [&] { return all_equal(r.get(), N, sentinel) && all_equal(g.get(), N, sentinel) && all_equal(b.get(), N, sentinel); };
    const soa_rgba<T> out{std::span<T>(r.get(), N), std::span<T>(g.get(), N), std::span<T>(b.get(), N), {}};

    // ---- span lengths ----
    {
        auto short_r = buffer<T>(N - 5, sentinel);
        expect_report("output channel shorter than N", "shade_batch: the output is shorter than the points",
                      [&] { shade_batch<plain>(in.positions(), in.normals(), material<T>{}, the_lights<T>(),
                                               soa_rgba<T>{std::span<T>(short_r.get(), N - 5), out.g, out.b, {}}); },
                      [&] { return all_equal(short_r.get(), N - 5, sentinel) && out_clean(); });
        auto short_a = buffer<T>(N - 1, sentinel);
        expect_report("alpha channel shorter than N", "shade_batch: the output is shorter than the points",
                      [&] { shade_batch<with_alpha>(in.positions(), in.normals(), material<T>{}, the_lights<T>(),
                                                    soa_rgba<T>{out.r, out.g, out.b, std::span<T>(short_a.get(), N - 1)}); },
                      [&] { return all_equal(short_a.get(), N - 1, sentinel) && out_clean(); });
        auto colours = buffer<glm::vec<3, T>>(N - 3, glm::vec<3, T>(sentinel));
        expect_report("interleaved output shorter than N", "shade_batch: the output is shorter than the points",
                      [&] { shade_batch<plain>(in.positions(), in.normals(), material<T>{}, the_lights<T>(),
                                               std::span<glm::vec<3, T>>(colours.get(), N - 3)); },
                      [&] { return all_equal(colours.get(), N - 3, glm::vec<3, T>(sentinel)); });
    }
    expect_report("normals shorter than N", "shade_batch: .normals: not one normal per point",
                  [&] { shade_batch<plain>(in.positions(), in.normals(N - 1), material<T>{}, the_lights<T>(), out); }, out_clean);
    expect_report("normals.x alone shorter", "shade_batch: .normals: not one normal per point", [&] {
        const soa3<T> nrm{std::span<const T>(in.nx.get(), N - 2), std::span<const T>(in.ny.get(), N), std::span<const T>(in.nz.get(), N)};
        shade_batch<plain>(in.positions(), nrm, material<T>{}, the_lights<T>(), out);
    }, out_clean);
    expect_report("positions.y shorter than x", "shade_batch: .positions: x, y and z of different lengths",
                  [&] { shade_batch<plain>(in.positions(N, N - 1, N), in.normals(), material<T>{}, the_lights<T>(), out); }, out_clean);
    expect_report("positions.z shorter than x", "shade_batch: .positions: x, y and z of different lengths",
                  [&] { shade_batch<plain>(in.positions(N, N, 3), in.normals(), material<T>{}, the_lights<T>(), out); }, out_clean);
    {
        auto mats = buffer<material<T>>(N - 4, material<T>{});
        expect_report("per-point materials shorter than N", "shade_batch: one material per point",
                      [&] { shade_batch<plain>(in.positions(), in.normals(), std::span<const material<T>>(mats.get(), N - 4), the_lights<T>(), out); },
                      out_clean);
        auto ids = buffer<std::uint32_t>(N - 1, 0u);
        expect_report("material_table ids shorter than N", "shade_batch: material_table needs one id per point (.ids)", [&] {
            shade_batch<plain>(soa_points<T>{in.positions(), in.normals()},
                               material_table<T>{std::span<const material<T>>(mats.get(), 2), std::span<const std::uint32_t>(ids.get(), N - 1)},
                               the_lights<T>(), out);
        }, out_clean);
        auto all_ids = buffer<std::uint32_t>(N, 0u);
        expect_report("material_table without materials", "shade_batch: material_table without materials", [&] {
            shade_batch<plain>(soa_points<T>{in.positions(), in.normals()},
                               material_table<T>{std::span<const material<T>>(), std::span<const std::uint32_t>(all_ids.get(), N)},
                               the_lights<T>(), out);
        }, out_clean);
    }
    {
        auto vx = buffer<T>(N, T(0)), vy = buffer<T>(N, T(0)), vz = buffer<T>(N - 6, T(1));
        const soa3<T> views{std::span<const T>(vx.get(), N), std::span<const T>(vy.get(), N), std::span<const T>(vz.get(), N - 6)};
        expect_report("views.z shorter (view_model::given)", "shade_batch: view_model::given needs one view vector per point (.views)",
                      [&] { shade_batch<given>(soa_points<T>{in.positions(), in.normals(), views}, material<T>{}, the_lights<T>(), out); },
                      out_clean);
        auto facing = buffer<bool>(N - 2, true);
        expect_report("front_facing shorter than N", "shade_batch: front_facing length", [&] {
            shade_batch<plain>(soa_points<T>{in.positions(), in.normals(), {}, std::span<const bool>(facing.get(), N - 2)}, material<T>{},
                               the_lights<T>(), out);
        }, out_clean);
        auto masks = buffer<std::uint64_t>(N - 2, ~std::uint64_t(0));
        expect_report("light_masks shorter than N", "shade_batch: light_masks length", [&] {
            shade_batch<plain>(soa_points<T>{in.positions(), in.normals(), {}, {}, std::span<const std::uint64_t>(masks.get(), N - 2)},
                               material<T>{}, the_lights<T>(), out);
        }, out_clean);
        auto apos = buffer<glm::vec<3, T>>(N, glm::vec<3, T>(T(0.25), T(-0.5), T(-4)));
        auto anrm = buffer<glm::vec<3, T>>(N - 1, glm::vec<3, T>(T(0), T(0), T(1)));
        expect_report("AoS normals shorter than N", "shade_batch: .normals: not one normal per point", [&] {
            shade_batch<plain>(aos_points<T>{std::span<const glm::vec<3, T>>(apos.get(), N), std::span<const glm::vec<3, T>>(anrm.get(), N - 1)},
                               material<T>{}, the_lights<T>(), out);
        }, out_clean);
    }

    // ---- overlaps: each message names the written span and the read one ----
    {
        // One block holding an input column and the output: out.r = x shifted by one element.
        auto block = buffer<T>(N + 1, T(0.25));
        const auto block_clean = [&] { return all_equal(block.get(), N + 1, T(0.25)) && all_equal(g.get(), N, sentinel); };
        const soa3<T> pos{std::span<const T>(block.get(), N), std::span<const T>(in.y.get(), N), std::span<const T>(in.z.get(), N)};
        expect_report("out.r over positions.x shifted by one", "shade_batch: an output span overlaps an input span: out.r over .positions.x",
                      [&] { shade_batch<plain>(pos, in.normals(), material<T>{}, the_lights<T>(), soa_rgba<T>{std::span<T>(block.get() + 1, N), out.g, out.b, {}}); },
                      block_clean);
        auto nblock = buffer<T>(N + 3, T(0.5));
        const soa3<T> nrm{std::span<const T>(in.nx.get(), N), std::span<const T>(nblock.get() + 3, N), std::span<const T>(in.nz.get(), N)};
        expect_report("out.g over normals.y", "shade_batch: an output span overlaps an input span: out.g over .normals.y",
                      [&] { shade_batch<plain>(in.positions(), nrm, material<T>{}, the_lights<T>(), soa_rgba<T>{out.r, std::span<T>(nblock.get(), N), out.b, {}}); },
                      [&] { return all_equal(nblock.get(), N + 3, T(0.5)) && all_equal(r.get(), N, sentinel); });
    }
    expect_report("out.b the same memory as out.r", "shade_batch: an output span overlaps another output span: out.b over out.r",
                  [&] { shade_batch<plain>(in.positions(), in.normals(), material<T>{}, the_lights<T>(), soa_rgba<T>{out.r, out.g, out.r, {}}); },
                  out_clean);
    {
        auto ra = buffer<T>(N + 3, sentinel);
        expect_report("out.a over out.r (F.alpha)", "shade_batch: an output span overlaps another output span: out.a over out.r", [&] {
            shade_batch<with_alpha>(in.positions(), in.normals(), material<T>{}, the_lights<T>(),
                                    soa_rgba<T>{std::span<T>(ra.get(), N), out.g, out.b, std::span<T>(ra.get() + 3, N)});
        }, [&] { return all_equal(ra.get(), N + 3, sentinel) && out_clean(); });
    }
    {
        auto mats = buffer<material<T>>(N, material<T>{});
        T* over = reinterpret_cast<T*>(mats.get()) + 1;
        const std::vector<material<T>> before(mats.get(), mats.get() + N);
        const auto mats_clean = [&] { return std::memcmp(before.data(), mats.get(), N * sizeof(material<T>)) == 0; };
        expect_report("out.r over per-point materials", "shade_batch: an output span overlaps an input span: out.r over materials", [&] {
            shade_batch<plain>(in.positions(), in.normals(), std::span<const material<T>>(mats.get(), N), the_lights<T>(),
                               soa_rgba<T>{std::span<T>(over, N), out.g, out.b, {}});
        }, mats_clean);
        expect_report("out.g over the table's materials", "shade_batch: an output span overlaps an input span: out.g over material_table.materials", [&] {
            auto ids = buffer<std::uint32_t>(N, 0u);
            shade_batch<plain>(soa_points<T>{in.positions(), in.normals()},
                               material_table<T>{std::span<const material<T>>(mats.get(), N), std::span<const std::uint32_t>(ids.get(), N)},
                               the_lights<T>(), soa_rgba<T>{out.r, std::span<T>(over, N), out.b, {}});
        }, mats_clean);
        static_assert(sizeof(T) >= sizeof(std::uint32_t));
        auto ids = buffer<std::uint32_t>(N * sizeof(T) / sizeof(std::uint32_t), 0u);
        expect_report("out.r over the table's ids", "shade_batch: an output span overlaps an input span: out.r over material_table.ids", [&] {
            shade_batch<plain>(soa_points<T>{in.positions(), in.normals()},
                               material_table<T>{std::span<const material<T>>(mats.get(), 1), std::span<const std::uint32_t>(ids.get(), N)},
                               the_lights<T>(), soa_rgba<T>{std::span<T>(reinterpret_cast<T*>(ids.get()), N), out.g, out.b, {}});
        }, [&] { return all_equal(ids.get(), N * sizeof(T) / sizeof(std::uint32_t), 0u); });
    }
    {
        auto flags = buffer<T>(N, T(0)); // storage for N bools and more
        bool* facing = reinterpret_cast<bool*>(flags.get());
        for (std::size_t i = 0; i < N; ++i) facing[i] = true;
        expect_report("out.b over front_facing", "shade_batch: an output span overlaps an input span: out.b over .front_facing", [&] {
            shade_batch<plain>(soa_points<T>{in.positions(), in.normals(), {}, std::span<const bool>(facing, N)}, material<T>{}, the_lights<T>(),
                               soa_rgba<T>{out.r, out.g, std::span<T>(flags.get(), N), {}});
        }, [&] { return all_equal(facing, N, true) && all_equal(r.get(), N, sentinel); });
        auto masks = buffer<std::uint64_t>(N, ~std::uint64_t(0));
        expect_report("out.r over light_masks", "shade_batch: an output span overlaps an input span: out.r over .light_masks", [&] {
            shade_batch<plain>(soa_points<T>{in.positions(), in.normals(), {}, {}, std::span<const std::uint64_t>(masks.get(), N)}, material<T>{},
                               the_lights<T>(), soa_rgba<T>{std::span<T>(reinterpret_cast<T*>(masks.get()) + 1, N), out.g, out.b, {}});
        }, [&] { return all_equal(masks.get(), N, ~std::uint64_t(0)); });
        auto vx = buffer<T>(N + 1, T(0)), vy = buffer<T>(N, T(0)), vz = buffer<T>(N, T(1));
        const soa3<T> views{std::span<const T>(vx.get() + 1, N), std::span<const T>(vy.get(), N), std::span<const T>(vz.get(), N)};
        expect_report("out.r over views.x (view_model::given)", "shade_batch: an output span overlaps an input span: out.r over .views.x", [&] {
            shade_batch<given>(soa_points<T>{in.positions(), in.normals(), views}, material<T>{}, the_lights<T>(),
                               soa_rgba<T>{std::span<T>(vx.get(), N), out.g, out.b, {}});
        }, [&] { return all_equal(vx.get(), N + 1, T(0)); });
    }
    {
        auto apos = buffer<glm::vec<3, T>>(N + 1, glm::vec<3, T>(T(0.25), T(-0.5), T(-4)));
        auto anrm = buffer<glm::vec<3, T>>(N, glm::vec<3, T>(T(0), T(0), T(1)));
        const auto pos_clean = [&] { return all_equal(apos.get(), N + 1, glm::vec<3, T>(T(0.25), T(-0.5), T(-4))); };
        expect_report("AoS output over AoS positions", "shade_batch: an output span overlaps an input span: the output over .positions", [&] {
            shade_batch<plain>(aos_points<T>{std::span<const glm::vec<3, T>>(apos.get() + 1, N), std::span<const glm::vec<3, T>>(anrm.get(), N)},
                               material<T>{}, the_lights<T>(), std::span<glm::vec<3, T>>(apos.get(), N));
        }, pos_clean);
        expect_report("SoA output over AoS normals", "shade_batch: an output span overlaps an input span: out.g over .normals", [&] {
            shade_batch<plain>(aos_points<T>{std::span<const glm::vec<3, T>>(apos.get(), N), std::span<const glm::vec<3, T>>(anrm.get(), N)},
                               material<T>{}, the_lights<T>(), soa_rgba<T>{out.r, std::span<T>(reinterpret_cast<T*>(anrm.get()) + 2, N), out.b, {}});
        }, [&] { return all_equal(anrm.get(), N, glm::vec<3, T>(T(0), T(0), T(1))); });
    }

    // ---- the valid calls next to them: no report, every colour written ----
    reported.clear();
    shade_batch<plain>(in.positions(), in.normals(), material<T>{}, the_lights<T>(), out);
    auto x_copy = buffer<T>(N, T(0.25));
    shade_batch<plain>(soa3<T>{std::span<const T>(x_copy.get(), N), std::span<const T>(in.y.get(), N), std::span<const T>(in.z.get(), N)},
                       in.normals(), material<T>{}, the_lights<T>(), soa_rgba<T>{std::span<T>(x_copy.get(), N), out.g, out.b, {}}); // in place
    const bool written = !all_equal(r.get(), N, sentinel) && x_copy[N - 1] == r[N - 1];
    if (!reported.empty() || !written) {
        ++failures;
        std::printf("FAIL valid calls: %zu reports, colours %s\n", reported.size(), written ? "written" : "NOT written");
    } else {
        std::printf("ok   valid calls (out of place and in place): no report, colours written\n");
    }
}

} // namespace

int main()
{
    phong::set_precondition_handler(&record); // records and returns: shade_batch must then write nothing
    run<float>("float");
    run<double>("double");
#if defined(NDEBUG)
    std::printf("(NDEBUG build)\n");
#endif
    std::printf("%d failed\n", failures);
    return failures == 0 ? 0 : 1;
}
