// interlock in deal.II: a rough rock joint between two rock blocks (scenes shear, block), or
// the pull-out test (scene pullout), in a p4est-distributed hexahedral mesh. An interface is
// a thin layer of hexahedral cells (thickness h); at each of the layer's quadrature points the
// interlock law (through its C API, batched over every point of the process) gives the
// traction and the consistent tangent from the separation s = h (eps_nn, 2 eps_nt1, 2 eps_nt2)
// in the point's frame (n = z, t1 = x, t2 = y for the joint). The other strain components of
// the layer are linear elastic (modulus e_other), the solids isotropic elastic.
//
// Scene pullout: the paper's pull-out test (a bar in a concrete block, a clay-bar and a
// concrete-bar layer, the frame n radial at each point, t1 along the bar, t2 around it): the
// grip pulls the bar's top face, then twists it; make_pullout_grid and pullout_constraints.
//
// Loading (a direct-shear machine): the bottom face is fixed; the top face is a rigid platen
// whose in-plane displacement is prescribed and whose normal displacement is one unknown
// carrying the normal force sigma_N A. Increment 1 applies sigma_N at zero slip, increments
// 2 .. n_slip + 1 slide the platen by slip / n_slip each along angle_deg from x.
//
// Newton with the law's consistent tangent; a direct solve (MUMPS through PETSc) or GMRES with
// BoomerAMG; an increment is cut back when a point fails or asks for a cut (its step fraction
// < 1 at the converged iterate). The quadrature-point state lives with the cells
// (CellDataStorage) and is packed with them for a checkpoint (Triangulation::save), so a
// restart on any number of processes continues the run. docs/dealii.md describes it all.

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/quadrature_point_data.h>
#include <deal.II/base/utilities.h>

#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/petsc_precondition.h>
#include <deal.II/lac/petsc_solver.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/vector.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <interlock.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace interlock_dealii
{
  using namespace dealii;
  constexpr int dim = 3;

  // The paper's pull-out test (section 4.2): bar diameter D = 19.5 mm, a clay sleeve over the
  // top 10 D, the steel's first yield stress (Table 3).
  constexpr double bar_radius    = 19.5 / 2;
  constexpr double sleeve_length = 10 * 19.5;
  constexpr double steel_yield   = 350.0;

  // What a run does: key=value arguments on the command line (docs/dealii.md lists them).
  struct Settings
  {
    std::string  scene            = "shear";
    unsigned int n_xy             = 2;    // cells across the joint, each way
    unsigned int n_block          = 0;    // cell layers of each rock block (0: the joint only)
    unsigned int refine           = 0;    // global refinements of that mesh
    double       length           = 10.0; // side of the square joint [mm]
    double       layer            = 0.1;  // thickness h of the layer [mm]
    double       block            = 5.0;  // thickness of each block [mm]
    double       e_block          = 50000.0; // Young's modulus of the rock [MPa]
    double       nu_block         = 0.25;
    double       e_other          = 1.0;  // the layer's in-plane moduli [MPa]
    double       normal           = -1.5; // sigma_N [MPa]
    double       slip             = 2.0;  // platen slip [mm]
    double       angle_deg        = 45.0; // slip direction from x (t1) [deg]
    unsigned int n_slip           = 40;   // increments of slip
    bool         accuracy_cuts    = true; // the law's step-fraction requests (damage, angle)
    std::string  solver           = "mumps"; // mumps | gmres (BoomerAMG)
    std::string  output_dir       = ".";
    std::string  curve            = "curve.csv";
    unsigned int vtu_every        = 0;    // write VTU/PVTU every k increments (0: never)
    int          checkpoint_after = -1;   // save a checkpoint after increment k and stop
    bool         restart          = false; // continue from output_dir's checkpoint
    unsigned int max_iterations   = 25;
    unsigned int verbose          = 0;    // 1: every Newton iteration's residual and cut
    double       tolerance        = 1e-10; // residual / (|sigma_N| A), pullout: / (f_y A_bar)
    // Scene pullout (the paper's pull-out test, section 4.2): a bar in a concrete cylinder.
    unsigned int n_theta          = 16;   // cells around the bar (a multiple of 4)
    double       element          = 10.0; // cell length along the bar [mm]
    double       embedment        = 235.0; // the bar's embedded length [mm]
    double       radius           = 500.0; // the block's radius [mm]
    double       ring_first       = 10.0; // the first concrete ring's width [mm]
    double       ring_ratio       = 1.5;  // each concrete ring this much wider than the last
    double       e_steel          = 190000.0, nu_steel = 0.3;   // Table 3
    double       e_concrete       = 2621.0, nu_concrete = 0.2;  // Table 3 as printed
    double       pull             = 1.3;  // the grip's axial displacement [mm]
    unsigned int n_pull           = 25;   // in n_pull increments
    double       twist_deg        = 0.0;  // then the grip's rotation about the axis [deg]
    unsigned int n_twist          = 0;    // in n_twist increments

    void
    parse(int argc, char **argv);
  };

  void
  Settings::parse(int argc, char **argv)
  {
    // A scene first sets its defaults; later arguments override them.
    std::map<std::string, std::string> given;
    for (int i = 1; i < argc; ++i)
      {
        const std::string arg = argv[i];
        const auto        eq  = arg.find('=');
        if (eq == std::string::npos)
          throw std::invalid_argument("argument '" + arg + "' is not key=value");
        given[arg.substr(0, eq)] = arg.substr(eq + 1);
      }
    if (given.count("scene"))
      scene = given["scene"];
    if (scene == "shear")
      {
        // The joint alone between rigid platens: every point of the layer has the platen's
        // separation, so the layer is interlock-history's point (tests/mpi/test_dealii.py).
        n_xy          = 2;
        n_block       = 0;
        accuracy_cuts = false;
      }
    else if (scene == "block")
      {
        // The joint between elastic rock blocks with free sides: a non-uniform joint. With
        // 4 x 4 cells the platen's dof is not locally relevant on every process at np 2 and 4.
        n_xy    = 4;
        n_block = 1;
        n_slip  = 20;
      }
    else if (scene == "pullout")
      {
        // The pull-out test in 3D: the interfaces' PROPS as the CalculiX model's
        // (examples/calculix/pullout/make_mesh.py): accuracy bounds off, e_other 0.01 MPa.
        layer         = 0.01;
        e_other       = 0.01;
        accuracy_cuts = false;
      }
    else
      throw std::invalid_argument("scene = '" + scene +
                                  "': admissible shear, block or pullout");
    const std::map<std::string, double *> reals = {
      {"length", &length},   {"layer", &layer},       {"block", &block},
      {"e_block", &e_block}, {"nu_block", &nu_block}, {"e_other", &e_other},
      {"normal", &normal},   {"slip", &slip},         {"angle_deg", &angle_deg},
      {"tolerance", &tolerance}, {"element", &element}, {"embedment", &embedment},
      {"radius", &radius},   {"ring_first", &ring_first}, {"ring_ratio", &ring_ratio},
      {"e_steel", &e_steel}, {"nu_steel", &nu_steel}, {"e_concrete", &e_concrete},
      {"nu_concrete", &nu_concrete}, {"pull", &pull}, {"twist_deg", &twist_deg}};
    const std::map<std::string, unsigned int *> counts = {
      {"n_xy", &n_xy},           {"n_block", &n_block},     {"refine", &refine},
      {"n_slip", &n_slip},       {"vtu_every", &vtu_every}, {"max_iterations", &max_iterations},
      {"verbose", &verbose},     {"n_theta", &n_theta},     {"n_pull", &n_pull},
      {"n_twist", &n_twist}};
    const std::map<std::string, bool *>        flags = {{"accuracy_cuts", &accuracy_cuts},
                                                        {"restart", &restart}};
    const std::map<std::string, std::string *> texts = {{"solver", &solver},
                                                        {"output_dir", &output_dir},
                                                        {"curve", &curve}};
    for (const auto &kv : given)
      {
        const std::string &k = kv.first, &v = kv.second;
        try
          {
            size_t used = v.size();
            if (k == "scene")
              continue;
            else if (reals.count(k))
              *reals.at(k) = std::stod(v, &used);
            else if (counts.count(k))
              *counts.at(k) = static_cast<unsigned int>(std::stoul(v, &used));
            else if (flags.count(k))
              *flags.at(k) = (std::stoi(v, &used) != 0);
            else if (texts.count(k))
              *texts.at(k) = v;
            else if (k == "checkpoint_after")
              checkpoint_after = std::stoi(v, &used);
            else
              throw std::invalid_argument("unknown setting '" + k + "'");
            if (used != v.size())
              throw std::invalid_argument("");
          }
        catch (const std::logic_error &e) // stod and friends: invalid_argument, out_of_range
          {
            if (std::string(e.what()).rfind("unknown setting", 0) == 0)
              throw;
            throw std::invalid_argument("setting " + k + " = '" + v + "' is not a valid value");
          }
      }
    if (solver != "mumps" && solver != "gmres")
      throw std::invalid_argument("solver = '" + solver + "': admissible mumps or gmres");
    if (n_xy == 0 || n_slip == 0 || !(layer > 0) || !(length > 0) || !(block > 0))
      throw std::invalid_argument("n_xy, n_slip, layer, length and block must be positive");
    if (scene == "pullout" &&
        (n_theta < 4 || n_theta % 4 != 0 || !(element > 0) || n_pull == 0 ||
         !(embedment > sleeve_length + element) || !(radius > bar_radius + layer + ring_first) ||
         !(ring_first > 0) || !(ring_ratio >= 1) || (twist_deg != 0 && n_twist == 0)))
      throw std::invalid_argument(
        "pullout: n_theta a multiple of 4, element, ring_first and n_pull > 0, embedment > " +
        std::to_string(sleeve_length) + " + element, radius > the bar's + layer + ring_first, "
        "ring_ratio >= 1, n_twist > 0 with a twist");
  }

  // The state of one quadrature point of the layer: the C API's state (the UMAT's STATEV,
  // then the separation and the traction) at the last accepted increment. The Newton
  // iterate's state lives in the batch (JointProblem::batch_new) until the increment is
  // accepted.
  struct PointState
  {
    std::vector<double> committed;
  };

  using Material = std::unique_ptr<interlock_material, void (*)(interlock_material *)>;

  // The granite joint of the shipped 3D decks (inputs/granite_3d_*.nml): the azimuthal RIA
  // with 3 azimuths. Without accuracy cuts the step-fraction bounds are at their widest.
  Material
  granite_joint(const bool accuracy_cuts)
  {
    std::vector<const char *> names = {"sigma0_n", "sigma0_t", "gc", "eta", "mu",
                                       "h_n", "theta0_deg", "thetaf_deg", "zeta0",
                                       "ria", "n_azimuths"};
    std::vector<double> values = {0.025, 0.025, 0.0005, 0.99, 0.6898538,
                                  4.0, 30.0, 9.0, 6.666, 1.0, 3.0};
    if (!accuracy_cuts)
      {
        names.push_back("max_damage_increment");
        values.push_back(1.0);
        names.push_back("max_angle_increment_deg");
        values.push_back(90.0);
      }
    interlock_material *m = nullptr;
    char                message[512];
    if (interlock_material_from_names(dim, static_cast<int>(names.size()), names.data(),
                                      values.data(), &m, message, sizeof message) !=
        INTERLOCK_OK)
      throw std::runtime_error(std::string("interlock refuses the material: ") + message);
    return {m, interlock_material_free};
  }

  // The pull-out test's interfaces (the paper's Table 5) with the CalculiX model's PROPS
  // (examples/calculix/pullout/make_mesh.py): the paper's RIA (ridges across t1, the bar's
  // ribs), wear on, theta_f = 0, the implicit scheme, the accuracy bounds at their widest
  // unless asked; the exact tangent (the MUMPS solve is unsymmetric). Layer id 1: clay-bar,
  // layer id 2: concrete-bar.
  std::vector<Material>
  pullout_interfaces(const bool accuracy_cuts)
  {
    // sigma0_n = sigma0_t, Gc, eta, mu, H_N, theta_0, theta_f, zeta_0
    const double table5[2][8] = {{0.5, 0.05, 0.995, 0.6, 0.5, 1.75, 0.0, 33.3},
                                 {1.0, 0.1, 0.995, 0.7, 1.5, 45.0, 0.0, 33.3}};
    std::vector<Material> out;
    for (const auto &t : table5)
      {
        const std::vector<double> props = {t[0], t[0], t[1], t[2], t[3], t[4], t[5], t[6], t[7],
                                           0.0, 2.0, 0.0, accuracy_cuts ? 0.25 : 1.0,
                                           accuracy_cuts ? 1.0 : 90.0, 1, 1, 1, 1, 1};
        interlock_material *m = nullptr;
        char                message[512];
        if (interlock_material_from_props(dim, static_cast<int>(props.size()), props.data(), &m,
                                          message, sizeof message) != INTERLOCK_OK)
          throw std::runtime_error(std::string("interlock refuses an interface: ") + message);
        out.emplace_back(m, interlock_material_free);
      }
    return out;
  }

  std::vector<Material>
  scene_materials(const Settings &settings)
  {
    if (settings.scene == "pullout")
      return pullout_interfaces(settings.accuracy_cuts);
    std::vector<Material> out;
    out.push_back(granite_joint(settings.accuracy_cuts));
    return out;
  }

  // Seconds spent in each part of the Newton iterations: wall clock, and the process's CPU
  // time (what a loaded machine does not inflate; it counts an MPI wait that spins).
  struct Cost
  {
    double       law = 0, assembly = 0, solve = 0;
    double       law_cpu = 0, assembly_cpu = 0, solve_cpu = 0;
    unsigned int iterations = 0;
  };

  inline double
  cpu_seconds()
  {
    return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
  }

  class JointProblem
  {
  public:
    JointProblem(const Settings &settings);
    void
    run();

  private:
    using Clock = std::chrono::steady_clock;

    void
    make_grid();
    void
    make_pullout_grid();
    void
    setup_system();
    void
    platen_constraints();
    void
    pullout_constraints();
    void
    initialise_state();
    void
    set_platen(const double t);
    bool
    assemble(Cost &cost, double &min_fraction);
    void
    solve(Cost &cost);
    bool
    newton(Cost &cost, unsigned int &iterations, double &min_fraction);
    void
    commit_state();
    std::string
    curve_row(const unsigned int increment, const double t, const unsigned int substeps,
              const unsigned int iterations);
    std::vector<double>
    layer_sums();
    std::string
    pullout_curve_row(const unsigned int increment, const double t, const unsigned int substeps,
                      const unsigned int iterations);
    void
    write_vtu(const unsigned int increment);
    void
    save_checkpoint(const unsigned int increment, const double t);
    unsigned int
    load_checkpoint(double &t);

    double
    normal_factor(const double t) const
    {
      return pullout ? 0.0 : std::min(t, 1.0);
    }
    double
    slip_at(const double t) const
    {
      return (pullout || t <= 1.0) ? 0.0 : settings.slip * (t - 1.0) / settings.n_slip;
    }
    // Pull-out: the grip's axial displacement [mm] and rotation [rad] at time t (increments
    // 1 .. n_pull pull, then n_twist twist).
    double
    pull_at(const double t) const
    {
      return settings.pull * std::min(t, double(settings.n_pull)) / settings.n_pull;
    }
    double
    twist_at(const double t) const
    {
      return t <= settings.n_pull ? 0.0 :
                                    settings.twist_deg * numbers::PI / 180.0 *
                                      (t - settings.n_pull) / settings.n_twist;
    }
    // The loading phase's start (normal load, then slip; pull, then twist): a substep carries
    // the last substep's rate on only within one phase, and not in the normal load.
    double
    phase_start(const double t_new) const
    {
      const double b = pullout ? double(settings.n_pull) : 1.0;
      return t_new > b + 1e-12 ? b : 0.0;
    }
    bool
    in_layer(const typename Triangulation<dim>::cell_iterator &cell) const
    {
      return cell->material_id() == layer_id || cell->material_id() == layer2_id;
    }
    const interlock_material *
    material_of(const typename Triangulation<dim>::cell_iterator &cell) const
    {
      return materials[cell->material_id() == layer2_id ? 1 : 0].get();
    }
    // The layer's frame at a quadrature point x (rows n, t1, t2): scenes shear and block
    // n = z, t1 = x, t2 = y; pull-out n radial at x, t1 = z along the bar towards the loaded
    // end, t2 = n x t1 (around the bar).
    Tensor<2, dim>
    layer_frame(const Point<dim> &x) const;
    // Pull-out: a radius between the bar's surface and the layer's outer face (the polygons'
    // vertex radii).
    double
    pullout_bar_edge() const
    {
      const double n = settings.n_theta;
      return bar_radius * std::sqrt((2 * numbers::PI / n) / std::sin(2 * numbers::PI / n)) +
             0.5 * settings.layer;
    }

    Settings                                  settings;
    MPI_Comm                                  comm;
    ConditionalOStream                        pcout;
    parallel::distributed::Triangulation<dim> triangulation;
    FESystem<dim>                             fe;
    DoFHandler<dim>                           dof_handler;
    QGauss<dim>                               quadrature;
    QGauss<dim - 1>                           face_quadrature;
    const bool                                pullout;
    std::vector<Material>                     materials; // layer ids 1, 2
    unsigned int                              state_size;
    unsigned int                              statev_size;
    std::vector<unsigned int>                 damage_slots;

    IndexSet                          owned_dofs, relevant_dofs;
    AffineConstraints<double>         constraints; // homogeneous: Newton's corrections
    types::global_dof_index           platen_dof = 0; // the platen's normal displacement
    PETScWrappers::MPI::SparseMatrix  matrix;
    PETScWrappers::MPI::Vector        solution, ghosted, rhs;
    // The solution before the last accepted substep of the slip phase and that substep's
    // length: the predictor of the next substep (0: none).
    PETScWrappers::MPI::Vector        previous;
    double                            dt_previous = 0;

    CellDataStorage<typename Triangulation<dim>::cell_iterator, PointState> storage;

    // The batch of the process's layer points handed to interlock_update at once.
    std::vector<double> batch_separation, batch_old, batch_new, batch_traction, batch_tangent,
      batch_fraction;
    std::vector<int> batch_status;

    std::vector<std::string> curve_rows;
    double                   top_z          = 0;
    double                   current_normal = 0; // sigma_N of the increment's end [MPa]
    double                   force_scale    = 1; // |sigma_N| A: the residual's scale [N]

    // Pull-out: the grip (the bar's top face) and the reaction plate (the concrete's top
    // face): per vertex of the top face on this process, its dofs and position.
    struct TopVertex
    {
      types::global_dof_index dof[dim];
      double                  x, y;
      bool                    bar;
    };
    std::vector<TopVertex> top_vertices;
    // The batch's first point of each locally owned layer cell (by active cell index).
    std::vector<size_t> batch_offset;
    // The grip's axial force [N] and torque about the axis [N mm]: this process's share at
    // the last assembly and at the last accepted substep.
    std::array<double, 2> grip_iterate{{0, 0}}, grip{{0, 0}};

    static constexpr types::material_id  layer_id = 1, layer2_id = 2, steel_id = 3;
    static constexpr types::boundary_id bottom_id = 4, top_id = 5; // colorize: z faces
  };

  JointProblem::JointProblem(const Settings &settings_)
    : settings(settings_)
    , comm(MPI_COMM_WORLD)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
    , triangulation(comm)
    , fe(FE_Q<dim>(1), dim)
    , dof_handler(triangulation)
    , quadrature(2)
    , face_quadrature(2)
    , pullout(settings.scene == "pullout")
    , materials(scene_materials(settings))
    , state_size(static_cast<unsigned int>(interlock_state_size(materials[0].get())))
    , statev_size(static_cast<unsigned int>(interlock_statev_size(materials[0].get())))
  {
    for (const auto &m : materials)
      if (interlock_state_size(m.get()) != static_cast<int>(state_size))
        throw std::runtime_error("the interfaces' states differ in size");
    const int n = interlock_state_variable_count(materials[0].get());
    for (int i = 0; i < n; ++i)
      {
        char   name[64], unit[16];
        int    plane = 0;
        double lo = 0, hi = 0;
        if (interlock_state_variable_info(materials[0].get(), i, name, sizeof name, unit,
                                          sizeof unit, &plane, &lo, &hi) == INTERLOCK_OK &&
            std::strcmp(name, "damage") == 0)
          damage_slots.push_back(static_cast<unsigned int>(i));
      }
  }

  // The box [0, L]^2 x [-B, h + B]: n_block cell layers of rock below and above one cell
  // layer of joint [0, h] (material id 1). Boundary ids from colorize: 4 bottom, 5 top.
  void
  JointProblem::make_grid()
  {
    if (pullout)
      {
        make_pullout_grid();
        return;
      }
    const double              L = settings.length, h = settings.layer, B = settings.block;
    std::vector<std::vector<double>> steps(dim);
    steps[0].assign(settings.n_xy, L / settings.n_xy);
    steps[1].assign(settings.n_xy, L / settings.n_xy);
    for (unsigned int i = 0; i < settings.n_block; ++i)
      steps[2].push_back(B / settings.n_block);
    steps[2].push_back(h);
    for (unsigned int i = 0; i < settings.n_block; ++i)
      steps[2].push_back(B / settings.n_block);
    const double bottom = settings.n_block > 0 ? -B : 0.0;
    top_z               = settings.n_block > 0 ? h + B : h;
    GridGenerator::subdivided_hyper_rectangle(triangulation, steps, Point<dim>(0, 0, bottom),
                                              Point<dim>(L, L, top_z), true);
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      {
        const double z = cell->center()[2];
        cell->set_material_id(z > 0 && z < h ? layer_id : 0);
      }
  }

  // The pull-out test's block: z from 0 (the bar's far end) to the embedment (the loaded end,
  // the block's top face), as the axisymmetric CalculiX model (x = radius, y = axis there).
  // The cross-section: the bar (a square core of m x m cells and one ring of n_theta = 4 m
  // cells to its surface), the layer (one ring, thickness h; clay-bar over the top 10 D,
  // concrete-bar below), the concrete (rings of growing width to the block's radius). Ring
  // vertices lie on polygons at uniform angles whose radius is scaled so that each polygon
  // has its circle's area (the bar's section exact); the layer's outer polygon lies h from
  // the inner one. Along the bar cells of about `element` mm, the sleeve's end a vertex row.
  // Boundary id 5: the top face.
  void
  JointProblem::make_pullout_grid()
  {
    const unsigned int n = settings.n_theta, m = n / 4;
    const double       h = settings.layer, L = settings.embedment;
    std::vector<double> radii = {bar_radius, bar_radius + h};
    for (double w = settings.ring_first; radii.back() < settings.radius - 1e-9;
         w *= settings.ring_ratio)
      radii.push_back(radii.back() + 1.5 * w >= settings.radius ? settings.radius :
                                                                   radii.back() + w);
    const double area_scale = std::sqrt((2 * numbers::PI / n) / std::sin(2 * numbers::PI / n));
    const double core       = 0.45 * bar_radius * area_scale; // the core square's half side

    // The section: core vertices (i, j), i, j = 0 .. m, then ring k's n vertices.
    std::vector<Point<2>> section;
    for (unsigned int j = 0; j <= m; ++j)
      for (unsigned int i = 0; i <= m; ++i)
        section.emplace_back(-core + 2 * core * i / m, -core + 2 * core * j / m);
    const auto core_vertex = [m](unsigned int i, unsigned int j) { return j * (m + 1) + i; };
    // The core's boundary counterclockwise from (-a, -a), position p = 0 .. n - 1; ring
    // vertex p at the angle -3 pi / 4 + 2 pi p / n (the core's corners at the diagonals).
    std::vector<unsigned int> perimeter(n);
    for (unsigned int k = 0; k < m; ++k)
      {
        perimeter[k]         = core_vertex(k, 0);
        perimeter[m + k]     = core_vertex(m, k);
        perimeter[2 * m + k] = core_vertex(m - k, m);
        perimeter[3 * m + k] = core_vertex(0, m - k);
      }
    // The layer's outer polygon: its faces h from the inner ones (the cells' thickness is the
    // layer's h, which the separation h eps assumes).
    std::vector<double> vertex_radii;
    for (const double r : radii)
      vertex_radii.push_back(r * area_scale);
    vertex_radii[1] = vertex_radii[0] + h / std::cos(numbers::PI / n);
    const unsigned int first_ring = section.size();
    for (const double r : vertex_radii)
      for (unsigned int p = 0; p < n; ++p)
        {
          const double phi = -0.75 * numbers::PI + 2 * numbers::PI * p / n;
          section.emplace_back(r * std::cos(phi), r * std::sin(phi));
        }
    const auto ring_vertex = [first_ring, n](unsigned int k, unsigned int p) {
      return first_ring + k * n + p % n;
    };
    // Section cells (vertices in deal.II's lexicographic order, counterclockwise) and their
    // kind: 0 concrete, 1 layer, 3 steel.
    std::vector<std::array<unsigned int, 4>> quads;
    std::vector<types::material_id>         kinds;
    for (unsigned int j = 0; j < m; ++j)
      for (unsigned int i = 0; i < m; ++i)
        {
          quads.push_back({{core_vertex(i, j), core_vertex(i + 1, j), core_vertex(i, j + 1),
                            core_vertex(i + 1, j + 1)}});
          kinds.push_back(steel_id);
        }
    for (unsigned int p = 0; p < n; ++p)
      {
        quads.push_back({{perimeter[p], ring_vertex(0, p), perimeter[(p + 1) % n],
                          ring_vertex(0, p + 1)}});
        kinds.push_back(steel_id);
      }
    for (unsigned int k = 0; k + 1 < radii.size(); ++k)
      for (unsigned int p = 0; p < n; ++p)
        {
          quads.push_back({{ring_vertex(k, p), ring_vertex(k + 1, p), ring_vertex(k, p + 1),
                            ring_vertex(k + 1, p + 1)}});
          kinds.push_back(k == 0 ? layer_id : 0);
        }

    // Along the bar.
    const double       lower    = L - sleeve_length;
    const auto cells_along = [this](const double length) {
      return std::max(1u, unsigned(std::lround(length / settings.element)));
    };
    const unsigned int n_sleeve = cells_along(sleeve_length), n_lower = cells_along(lower);
    std::vector<double> z;
    for (unsigned int k = 0; k <= n_lower; ++k)
      z.push_back(lower * k / n_lower);
    for (unsigned int k = 1; k <= n_sleeve; ++k)
      z.push_back(lower + sleeve_length * k / n_sleeve);
    top_z = L;

    const unsigned int     ns = section.size();
    std::vector<Point<dim>> vertices;
    for (const double zk : z)
      for (const auto &q : section)
        vertices.emplace_back(q[0], q[1], zk);
    std::vector<CellData<dim>> cells;
    for (unsigned int k = 0; k + 1 < z.size(); ++k)
      for (unsigned int c = 0; c < quads.size(); ++c)
        {
          CellData<dim> cell;
          for (unsigned int v = 0; v < 4; ++v)
            {
              cell.vertices[v]     = k * ns + quads[c][v];
              cell.vertices[v + 4] = (k + 1) * ns + quads[c][v];
            }
          const bool clay     = 0.5 * (z[k] + z[k + 1]) > lower;
          cell.material_id    = kinds[c] == layer_id && !clay ? layer2_id : kinds[c];
          cells.push_back(cell);
        }
    GridTools::consistently_order_cells(cells);
    triangulation.create_triangulation(vertices, cells, SubCellData());
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary() && std::abs(cell->face(f)->center()[2] - L) < 1e-9)
          cell->face(f)->set_boundary_id(top_id);
  }

  // The layer's frame (rows n, t1, t2). In the pull-out n is radial at the point itself,
  // not the normal of the cell's flat faces: a rigid rotation of the bar about its axis then
  // opens no point of the polygonal layer (with the faces' normal the polygon's corners
  // would bear like a key's, an opening of r sin(angle off the face's middle) per radian).
  Tensor<2, dim>
  JointProblem::layer_frame(const Point<dim> &x) const
  {
    Tensor<2, dim> q;
    if (!pullout)
      {
        q[0][2] = q[1][0] = q[2][1] = 1;
        return q;
      }
    const double r = std::hypot(x[0], x[1]);
    q[0][0]        = x[0] / r;
    q[0][1]        = x[1] / r;
    q[1][2]            = 1;
    q[2]               = cross_product_3d(q[0], q[1]);
    return q;
  }

  void
  JointProblem::setup_system()
  {
    dof_handler.distribute_dofs(fe);
    owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant_dofs);
    if (pullout)
      pullout_constraints();
    else
      platen_constraints();

    // The platen's row couples to every top-face dof of every process (the ties condense into
    // it): each process keeps its share of that row, even where the platen's dof is not
    // locally relevant, and hands it to the owner.
    IndexSet rows = relevant_dofs;
    if (!pullout)
      rows.add_index(platen_dof);
    DynamicSparsityPattern dsp(rows);
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    SparsityTools::distribute_sparsity_pattern(dsp, owned_dofs, comm, rows);
    matrix.reinit(owned_dofs, owned_dofs, dsp, comm);
    solution.reinit(owned_dofs, comm);
    previous.reinit(owned_dofs, comm);
    rhs.reinit(owned_dofs, comm);
    ghosted.reinit(owned_dofs, relevant_dofs, comm);
  }

  // Scenes shear and block: the bottom face fixed, the top face's in-plane displacement
  // prescribed, its normal displacements tied to the platen's one unknown.
  void
  JointProblem::platen_constraints()
  {
    // The platen's normal displacement: the smallest z dof of the top face, on every process.
    const FEValuesExtractors::Scalar     z_component(2);
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    std::vector<types::global_dof_index> top_z_dofs;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == top_id)
            {
              cell->face(f)->get_dof_indices(face_dofs);
              for (unsigned int i = 0; i < face_dofs.size(); ++i)
                if (fe.face_system_to_component_index(i).first == 2)
                  top_z_dofs.push_back(face_dofs[i]);
            }
    types::global_dof_index local_min = std::numeric_limits<types::global_dof_index>::max();
    for (const auto d : top_z_dofs)
      local_min = std::min(local_min, d);
    platen_dof = Utilities::MPI::min(local_min, comm);

    constraints.clear();
    constraints.reinit(relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    VectorTools::interpolate_boundary_values(dof_handler, bottom_id,
                                             Functions::ZeroFunction<dim>(dim), constraints);
    VectorTools::interpolate_boundary_values(dof_handler, top_id,
                                             Functions::ZeroFunction<dim>(dim), constraints,
                                             ComponentMask({true, true, false}));
    for (const auto d : top_z_dofs)
      if (d != platen_dof && !constraints.is_constrained(d))
        {
          constraints.add_line(d);
          constraints.add_entry(d, platen_dof, 1.0);
        }
    constraints.close();
  }

  // Pull-out: on the top face the grip holds the bar (its vertices with r <= the bar's):
  // u_z prescribed (the pull), the tangential displacement u_theta = -sin(phi) u_x +
  // cos(phi) u_y prescribed (the twist times r), the radial one free; the axis' vertex
  // u_x = u_y = 0. The reaction plate holds the concrete and the layer's outer vertices:
  // u_z = 0 and u_theta = 0 (it resists the twist's torque), radially free. Axisymmetric
  // pulling has u_theta = 0 everywhere: the u_theta ties only act in the twist. Homogeneous
  // here (Newton's corrections); set_platen puts the values into the solution.
  void
  JointProblem::pullout_constraints()
  {
    const double bar_edge = pullout_bar_edge();
    constraints.clear();
    constraints.reinit(relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    top_vertices.clear();
    std::map<types::global_dof_index, bool> seen;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == top_id)
            for (unsigned int v = 0; v < GeometryInfo<dim>::vertices_per_face; ++v)
              {
                TopVertex t;
                for (unsigned int c = 0; c < dim; ++c)
                  t.dof[c] = cell->face(f)->vertex_dof_index(v, c);
                if (seen.count(t.dof[0]))
                  continue;
                seen[t.dof[0]]   = true;
                const Point<dim> x = cell->face(f)->vertex(v);
                t.x                = x[0];
                t.y                = x[1];
                const double r     = std::hypot(t.x, t.y);
                t.bar              = r < bar_edge;
                if (owned_dofs.is_element(t.dof[0]))
                  top_vertices.push_back(t);
                if (constraints.is_constrained(t.dof[2]))
                  continue;
                constraints.add_line(t.dof[2]);
                if (r < 1e-9 * bar_radius)
                  {
                    constraints.add_line(t.dof[0]);
                    constraints.add_line(t.dof[1]);
                  }
                else if (std::abs(t.x) >= std::abs(t.y)) // u_y = (y / x) u_x + ...
                  {
                    constraints.add_line(t.dof[1]);
                    constraints.add_entry(t.dof[1], t.dof[0], t.y / t.x);
                  }
                else // u_x = (x / y) u_y + ...
                  {
                    constraints.add_line(t.dof[0]);
                    constraints.add_entry(t.dof[0], t.dof[1], t.x / t.y);
                  }
              }
    constraints.close();
  }

  // Virgin state at every quadrature point of the process's layer cells.
  void
  JointProblem::initialise_state()
  {
    const unsigned int nq = quadrature.size();
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && in_layer(cell))
        {
          storage.initialize(cell, nq);
          for (auto &p : storage.get_data(cell))
            {
              p->committed.resize(state_size);
              if (interlock_state_init(material_of(cell), 0, 1, p->committed.data()) !=
                  INTERLOCK_OK)
                throw std::runtime_error("interlock_state_init failed");
            }
        }
  }

  // The platen at time t: its in-plane displacement into the solution (bottom face 0).
  void
  JointProblem::set_platen(const double t)
  {
    if (pullout)
      {
        // The grip: u_z = the pull, u_theta = the twist x r (the tie's dependent component
        // from the independent one's current value); the plate: 0.
        const double pull = pull_at(t), omega = twist_at(t);
        std::vector<std::pair<types::global_dof_index, double>> values;
        for (const auto &v : top_vertices)
          {
            const double w = v.bar ? omega : 0.0, r2 = v.x * v.x + v.y * v.y;
            values.emplace_back(v.dof[2], v.bar ? pull : 0.0);
            if (r2 < 1e-18 * bar_radius * bar_radius)
              {
                values.emplace_back(v.dof[0], 0.0);
                values.emplace_back(v.dof[1], 0.0);
              }
            else if (std::abs(v.x) >= std::abs(v.y))
              values.emplace_back(v.dof[1], v.y / v.x * solution(v.dof[0]) + w * r2 / v.x);
            else
              values.emplace_back(v.dof[0], v.x / v.y * solution(v.dof[1]) - w * r2 / v.y);
          }
        for (const auto &kv : values)
          solution(kv.first) = kv.second;
        solution.compress(VectorOperation::insert);
        return;
      }
    const double a = settings.angle_deg * numbers::PI / 180.0, u = slip_at(t);
    std::map<types::global_dof_index, double> values;
    VectorTools::interpolate_boundary_values(dof_handler, bottom_id,
                                             Functions::ZeroFunction<dim>(dim), values);
    VectorTools::interpolate_boundary_values(
      dof_handler, top_id,
      Functions::ConstantFunction<dim>(std::vector<double>{u * std::cos(a), u * std::sin(a), 0.0}),
      values, ComponentMask({true, true, false}));
    for (const auto &kv : values)
      if (owned_dofs.is_element(kv.first))
        solution(kv.first) = kv.second;
    solution.compress(VectorOperation::insert);
  }

  // Voigt order (xx, yy, zz, yz, xz, xy) with engineering shears.
  using Voigt = std::array<double, 6>;
  inline Voigt
  voigt(const SymmetricTensor<2, dim> &e)
  {
    return {{e[0][0], e[1][1], e[2][2], 2 * e[1][2], 2 * e[0][2], 2 * e[0][1]}};
  }

  // The residual and the tangent at the current iterate (ghosted). The law runs once on every
  // layer point of the process (one batched call); returns false when a point fails.
  bool
  JointProblem::assemble(Cost &cost, double &min_fraction)
  {
    const auto         t0 = Clock::now();
    const double       c0 = cpu_seconds();
    const unsigned int nq = quadrature.size(), nd = fe.n_dofs_per_cell();
    const double       h  = settings.layer;
    FEValues<dim>      fv(fe, quadrature,
                     update_gradients | update_JxW_values | update_quadrature_points);
    FEFaceValues<dim>  ffv(fe, face_quadrature, update_values | update_JxW_values);
    const FEValuesExtractors::Vector     u(0);
    std::vector<SymmetricTensor<2, dim>> strain(nq);
    std::vector<types::global_dof_index> dofs(nd);

    // 1. The layer's separations in each point's frame, gathered with the old states into
    // the batch: the points of layer id 1, then those of layer id 2 (one call per material).
    size_t n = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && in_layer(cell))
        n += nq;
    batch_separation.resize(3 * n);
    batch_old.resize(state_size * n);
    batch_new.resize(state_size * n);
    batch_traction.resize(3 * n);
    batch_tangent.resize(9 * n);
    batch_status.resize(n);
    batch_fraction.resize(n);
    batch_offset.assign(triangulation.n_active_cells(), 0);
    std::vector<size_t> range(materials.size() + 1, 0);
    size_t              p = 0;
    for (unsigned int k = 0; k < materials.size(); ++k)
      {
        range[k] = p;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned() && in_layer(cell) && material_of(cell) == materials[k].get())
            {
              batch_offset[cell->active_cell_index()] = p;
              fv.reinit(cell);
              fv[u].get_function_symmetric_gradients(ghosted, strain);
              const auto data = storage.get_data(cell);
              for (unsigned int q = 0; q < nq; ++q, ++p)
                {
                  const Tensor<2, dim> frame = layer_frame(fv.quadrature_point(q));
                  const Tensor<1, dim> en    = strain[q] * frame[0];
                  for (unsigned int c = 0; c < 3; ++c)
                    batch_separation[3 * p + c] = (c == 0 ? h : 2 * h) * (frame[c] * en);
                  std::copy(data[q]->committed.begin(), data[q]->committed.end(),
                            batch_old.begin() + state_size * p);
                }
            }
      }
    range[materials.size()] = p;
    const auto   t1 = Clock::now();
    const double c1 = cpu_seconds();
    // 2. The law.
    size_t failed = 0;
    for (unsigned int k = 0; k < materials.size(); ++k)
      {
        const size_t a = range[k], m = range[k + 1] - range[k];
        failed += interlock_update(materials[k].get(), m, &batch_separation[3 * a],
                                   &batch_old[state_size * a], &batch_new[state_size * a],
                                   &batch_traction[3 * a], &batch_tangent[9 * a],
                                   &batch_status[a], &batch_fraction[a]);
      }
    const auto   t2 = Clock::now();
    const double c2 = cpu_seconds();
    cost.law_cpu += c2 - c1;
    min_fraction  = 1.0;
    for (size_t i = 0; i < n; ++i)
      min_fraction = std::min(min_fraction, batch_fraction[i]);
    min_fraction = Utilities::MPI::min(min_fraction, comm);
    const unsigned int any_failed =
      Utilities::MPI::max(static_cast<unsigned int>(failed > 0), comm);
    if (any_failed)
      {
        for (size_t i = 0; i < n; ++i)
          if (batch_status[i] != INTERLOCK_OK)
            {
              const unsigned int k =
                std::upper_bound(range.begin(), range.end(), i) - range.begin() - 1;
              char message[512];
              interlock_update_message(materials[k].get(), &batch_separation[3 * i],
                                       &batch_old[state_size * i], message, sizeof message);
              std::cout << "  process " << Utilities::MPI::this_mpi_process(comm)
                        << ": a layer point fails: " << message << std::endl;
              break;
            }
        cost.law += std::chrono::duration<double>(t2 - t1).count();
        cost.assembly += std::chrono::duration<double>(t1 - t0).count();
        cost.assembly_cpu += c1 - c0;
        return false;
      }

    // 3. Assembly. The solids' isotropic elasticity: the rock (scenes shear, block) or the
    // concrete, and the steel (pull-out).
    const auto isotropic = [](const double E, const double nu, double (&D)[6][6]) {
      const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
      for (unsigned int i = 0; i < 6; ++i)
        for (unsigned int j = 0; j < 6; ++j)
          D[i][j] = (i < 3 && j < 3) ? lambda : 0.0;
      for (unsigned int i = 0; i < 3; ++i)
        {
          D[i][i] += 2 * mu;
          D[i + 3][i + 3] = mu;
        }
    };
    double D_rock[6][6], D_steel[6][6];
    if (pullout)
      isotropic(settings.e_concrete, settings.nu_concrete, D_rock);
    else
      isotropic(settings.e_block, settings.nu_block, D_rock);
    isotropic(settings.e_steel, settings.nu_steel, D_steel);
    // The layer's law components in the local Voigt order (x = t1, y = t2, z = n):
    // normal zz (2), t1 xz (4), t2 yz (3).
    const unsigned int law_slot[3] = {2, 4, 3};
    matrix = 0;
    rhs    = 0;
    grip_iterate = {{0, 0}};
    const double bar_edge = pullout_bar_edge();
    FullMatrix<double>    cell_matrix(nd, nd);
    Vector<double>        cell_rhs(nd);
    std::vector<Voigt>    B(nd);
    double                D[6][6];
    Voigt                 stress;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell_matrix = 0;
          cell_rhs    = 0;
          fv.reinit(cell);
          fv[u].get_function_symmetric_gradients(ghosted, strain);
          const bool layer = in_layer(cell);
          // The layer's local axes at a point (t1, t2, n) as rows: a symmetric tensor e in
          // them is R e R^T.
          Tensor<2, dim> R;
          const auto local = [&R](const SymmetricTensor<2, dim> &e) {
            return voigt(symmetrize(Tensor<2, dim>(R * Tensor<2, dim>(e) * transpose(R))));
          };
          const auto &D_solid = cell->material_id() == steel_id ? D_steel : D_rock;
          p = layer ? batch_offset[cell->active_cell_index()] : 0;
          for (unsigned int q = 0; q < nq; ++q)
            {
              if (layer)
                {
                  const Tensor<2, dim> frame = layer_frame(fv.quadrature_point(q));
                  R[0]                       = frame[1];
                  R[1]                       = frame[2];
                  R[2]                       = frame[0];
                }
              const Voigt e = layer ? local(strain[q]) : voigt(strain[q]);
              if (layer)
                {
                  std::fill(&D[0][0], &D[0][0] + 36, 0.0);
                  D[0][0] = D[1][1] = D[5][5] = settings.e_other;
                  for (unsigned int a = 0; a < 3; ++a)
                    for (unsigned int b = 0; b < 3; ++b)
                      D[law_slot[a]][law_slot[b]] = h * batch_tangent[9 * p + 3 * a + b];
                  for (unsigned int i = 0; i < 6; ++i)
                    stress[i] = (i == 0 || i == 1 || i == 5) ? settings.e_other * e[i] : 0.0;
                  for (unsigned int a = 0; a < 3; ++a)
                    stress[law_slot[a]] = batch_traction[3 * p + a];
                  ++p;
                }
              else
                for (unsigned int i = 0; i < 6; ++i)
                  {
                    stress[i] = 0;
                    for (unsigned int j = 0; j < 6; ++j)
                      {
                        D[i][j] = D_solid[i][j];
                        stress[i] += D_solid[i][j] * e[j];
                      }
                  }
              const double w = fv.JxW(q);
              for (unsigned int i = 0; i < nd; ++i)
                B[i] = layer ? local(fv[u].symmetric_gradient(i, q)) :
                               voigt(fv[u].symmetric_gradient(i, q));
              for (unsigned int i = 0; i < nd; ++i)
                {
                  Voigt DBi_T{}; // row i of B^T D
                  for (unsigned int k = 0; k < 6; ++k)
                    {
                      double s = 0;
                      for (unsigned int l = 0; l < 6; ++l)
                        s += B[i][l] * D[l][k];
                      DBi_T[k] = s;
                    }
                  double r = 0;
                  for (unsigned int k = 0; k < 6; ++k)
                    r += B[i][k] * stress[k];
                  cell_rhs(i) -= r * w;
                  for (unsigned int j = 0; j < nd; ++j)
                    {
                      double s = 0;
                      for (unsigned int k = 0; k < 6; ++k)
                        s += DBi_T[k] * B[j][k];
                      cell_matrix(i, j) += s * w;
                    }
                }
            }
          // Pull-out: the grip's force and torque, the internal forces of the bar's top
          // vertices (Q1: shape function k of a component sits at vertex k).
          if (pullout && std::abs(cell->center()[2] - top_z) < cell->diameter())
            for (unsigned int i = 0; i < nd; ++i)
              {
                const auto       ci = fe.system_to_component_index(i);
                const Point<dim> x  = cell->vertex(ci.second);
                if (std::abs(x[2] - top_z) > 1e-9 * top_z || std::hypot(x[0], x[1]) > bar_edge)
                  continue;
                const double f = -cell_rhs(i);
                if (ci.first == 2)
                  grip_iterate[0] += f;
                else
                  grip_iterate[1] += (ci.first == 0 ? -x[1] : x[0]) * f;
              }
          // The platen's normal force sigma_N A, as a traction on the top face (the ties
          // carry it to the platen's one unknown).
          for (const auto f : cell->face_indices())
            if (!pullout && cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == top_id)
              {
                ffv.reinit(cell, f);
                for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                  for (unsigned int i = 0; i < nd; ++i)
                    if (fe.system_to_component_index(i).first == 2)
                      cell_rhs(i) += current_normal * ffv.shape_value(i, q) * ffv.JxW(q);
              }
          cell->get_dof_indices(dofs);
          constraints.distribute_local_to_global(cell_matrix, cell_rhs, dofs, matrix, rhs);
        }
    matrix.compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);
    const auto t3 = Clock::now();
    cost.assembly_cpu += (c1 - c0) + (cpu_seconds() - c2);
    cost.law += std::chrono::duration<double>(t2 - t1).count();
    cost.assembly += std::chrono::duration<double>((t1 - t0) + (t3 - t2)).count();
    return true;
  }

  // One Newton correction: K du = -r with the homogeneous constraints, then the ties and the
  // fixed components filled in.
  void
  JointProblem::solve(Cost &cost)
  {
    const auto                 t0 = Clock::now();
    const double               c0 = cpu_seconds();
    PETScWrappers::MPI::Vector du(owned_dofs, comm);
    if (settings.solver == "mumps")
      {
        SolverControl                    control(1, 0);
        PETScWrappers::SparseDirectMUMPS direct(control, comm);
        direct.solve(matrix, du, rhs);
      }
    else
      {
        // Inexact Newton: the correction to 1e-8 of the residual.
        SolverControl                 control(2000, 1e-8 * rhs.l2_norm());
        PETScWrappers::SolverGMRES    gmres(control, comm);
        PETScWrappers::PreconditionBoomerAMG amg(
          matrix, PETScWrappers::PreconditionBoomerAMG::AdditionalData());
        gmres.solve(matrix, du, rhs, amg);
      }
    constraints.distribute(du);
    solution += du;
    cost.solve += std::chrono::duration<double>(Clock::now() - t0).count();
    cost.solve_cpu += cpu_seconds() - c0;
  }

  // Newton on the increment whose end is already in the platen's values. False when a point
  // fails or the iterations do not converge; min_fraction is the smallest step fraction the
  // points ask for (at the converged iterate when true).
  bool
  JointProblem::newton(Cost &cost, unsigned int &iterations, double &min_fraction)
  {
    for (unsigned int it = 0;; ++it)
      {
        ghosted = solution;
        if (!assemble(cost, min_fraction))
          return false;
        const double r = rhs.l2_norm();
        if (settings.verbose > 0)
          pcout << "    iteration " << it << ": residual " << r / force_scale
                << ", smallest step fraction " << min_fraction << std::endl;
        if (!std::isfinite(r))
          return false;
        if (r <= settings.tolerance * force_scale)
          return true;
        if (it == settings.max_iterations)
          {
            min_fraction = 0.5;
            return false;
          }
        solve(cost);
        ++iterations;
        ++cost.iterations;
      }
  }

  // The converged iterate's states become the points' states.
  void
  JointProblem::commit_state()
  {
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && in_layer(cell))
        {
          size_t p = batch_offset[cell->active_cell_index()];
          for (auto &d : storage.get_data(cell))
            {
              std::copy(batch_new.begin() + state_size * p,
                        batch_new.begin() + state_size * (p + 1), d->committed.begin());
              ++p;
            }
        }
    grip = grip_iterate;
  }

  // Per layer material (ids 1, 2), over all processes: the layer's volume, then the
  // volume-weighted sums of the separation (3), the traction (3) and the damage (the mean over
  // the microplanes) at the last accepted increment.
  std::vector<double>
  JointProblem::layer_sums()
  {
    FEValues<dim>       fv(fe, quadrature, update_JxW_values);
    const unsigned int  nq = quadrature.size();
    std::vector<double> sums(8 * materials.size(), 0.0);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && in_layer(cell))
        {
          fv.reinit(cell);
          double *   sum  = &sums[cell->material_id() == layer2_id ? 8 : 0];
          const auto data = storage.get_data(cell);
          for (unsigned int q = 0; q < nq; ++q)
            {
              const double *s = data[q]->committed.data();
              const double  w = fv.JxW(q);
              sum[0] += w;
              for (unsigned int c = 0; c < 6; ++c)
                sum[1 + c] += w * s[statev_size + c];
              double d = 0;
              for (const auto k : damage_slots)
                d += s[k];
              sum[7] += w * d / std::max<size_t>(1, damage_slots.size());
            }
        }
    Utilities::MPI::sum(sums, comm, sums);
    return sums;
  }

  // One row of the curve: the platen's displacement, the layer's mean separation and traction
  // (area-weighted), mean damage and the largest departure of a point's traction from the mean.
  std::string
  JointProblem::curve_row(const unsigned int increment, const double t,
                          const unsigned int substeps, const unsigned int iterations)
  {
    if (pullout)
      return pullout_curve_row(increment, t, substeps, iterations);
    const std::vector<double> sums = layer_sums();
    std::array<double, 6>     mean;
    for (unsigned int c = 0; c < 6; ++c)
      mean[c] = sums[1 + c] / sums[0];
    double spread = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && in_layer(cell))
        for (const auto &d : storage.get_data(cell))
          for (unsigned int c = 3; c < 6; ++c)
            spread = std::max(spread, std::abs(d->committed[statev_size + c] - mean[c]));
    spread = Utilities::MPI::max(spread, comm);
    double uz = owned_dofs.is_element(platen_dof) ? solution(platen_dof) : 0.0;
    uz        = Utilities::MPI::sum(uz, comm);
    const double       a = settings.angle_deg * numbers::PI / 180.0, u = slip_at(t);
    std::ostringstream row;
    row << increment << ',' << substeps << ',' << iterations << std::setprecision(17) << ','
        << t << ',' << u * std::cos(a) << ',' << u * std::sin(a) << ',' << uz;
    for (unsigned int c = 0; c < 6; ++c)
      row << ',' << mean[c];
    row << ',' << sums[7] / sums[0] << ',' << spread;
    return row.str();
  }

  // Pull-out: the grip's pull [mm], twist [deg], force [N] and torque [N mm]; per interface
  // (clay-bar, concrete-bar) the area-weighted mean separation, traction and damage.
  std::string
  JointProblem::pullout_curve_row(const unsigned int increment, const double t,
                                  const unsigned int substeps, const unsigned int iterations)
  {
    const std::vector<double> sums = layer_sums();
    std::vector<double>       g(grip.begin(), grip.end());
    Utilities::MPI::sum(g, comm, g);
    std::ostringstream row;
    row << increment << ',' << substeps << ',' << iterations << std::setprecision(17) << ','
        << t << ',' << pull_at(t) << ',' << twist_at(t) * 180 / numbers::PI << ',' << g[0]
        << ',' << g[1];
    for (unsigned int k = 0; k < 2; ++k)
      for (unsigned int c = 1; c < 8; ++c)
        row << ',' << sums[8 * k + c] / std::max(sums[8 * k], 1e-300);
    return row.str();
  }

  std::string
  curve_header(const bool pullout)
  {
    if (pullout)
      return "increment,substeps,iterations,t,pull,twist_deg,force,torque,"
             "clay_s_n,clay_s_t1,clay_s_t2,clay_sigma_n,clay_sigma_t1,clay_sigma_t2,clay_damage,"
             "concrete_s_n,concrete_s_t1,concrete_s_t2,concrete_sigma_n,concrete_sigma_t1,"
             "concrete_sigma_t2,concrete_damage";
    return "increment,substeps,iterations,t,platen_ux,platen_uy,platen_uz,s_n,s_t1,s_t2,"
           "sigma_n,sigma_t1,sigma_t2,damage,traction_spread";
  }

  // Displacement, and per cell of the layer its mean damage, slip |s_T| and dilation s_N.
  void
  JointProblem::write_vtu(const unsigned int increment)
  {
    ghosted = solution;
    Vector<float> damage(triangulation.n_active_cells()), slip(triangulation.n_active_cells()),
      dilation(triangulation.n_active_cells()), rank(triangulation.n_active_cells());
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          rank(cell->active_cell_index()) = Utilities::MPI::this_mpi_process(comm);
          if (!in_layer(cell))
            continue;
          double     d = 0, s = 0, n = 0;
          const auto data = storage.get_data(cell);
          for (const auto &p : data)
            {
              const double *x = p->committed.data();
              for (const auto k : damage_slots)
                d += x[k] / damage_slots.size();
              s += std::hypot(x[statev_size + 1], x[statev_size + 2]);
              n += x[statev_size];
            }
          damage(cell->active_cell_index())   = d / data.size();
          slip(cell->active_cell_index())     = s / data.size();
          dilation(cell->active_cell_index()) = n / data.size();
        }
    DataOut<dim> out;
    out.attach_dof_handler(dof_handler);
    out.add_data_vector(ghosted, std::vector<std::string>(dim, "displacement"),
                        DataOut<dim>::type_dof_data,
                        std::vector<DataComponentInterpretation::DataComponentInterpretation>(
                          dim, DataComponentInterpretation::component_is_part_of_vector));
    out.add_data_vector(damage, "damage");
    out.add_data_vector(slip, "slip");
    out.add_data_vector(dilation, "dilation");
    out.add_data_vector(rank, "process");
    out.build_patches();
    out.write_vtu_with_pvtu_record(settings.output_dir + "/", pullout ? "pullout" : "joint",
                                   increment, comm, 4);
  }

  // The distributed mesh, the solution and every layer point's state (packed with its cell,
  // so a restart on another number of processes finds each state with its cell), and the
  // increment, time and curve so far (checkpoint.txt).
  void
  JointProblem::save_checkpoint(const unsigned int increment, const double t)
  {
    ghosted = solution;
    parallel::distributed::SolutionTransfer<dim, PETScWrappers::MPI::Vector> transfer(
      dof_handler);
    PETScWrappers::MPI::Vector ghosted_previous(owned_dofs, relevant_dofs, comm);
    ghosted_previous = previous;
    transfer.prepare_for_serialization(
      std::vector<const PETScWrappers::MPI::Vector *>{&ghosted, &ghosted_previous});
    const unsigned int nq = quadrature.size();
    triangulation.register_data_attach(
      [this, nq](const typename Triangulation<dim>::cell_iterator &cell,
                 const typename Triangulation<dim>::CellStatus) {
        std::vector<char> bytes;
        if (!in_layer(cell))
          return bytes;
        bytes.resize(nq * state_size * sizeof(double));
        char *b = bytes.data();
        for (const auto &p : storage.get_data(cell))
          {
            std::memcpy(b, p->committed.data(), state_size * sizeof(double));
            b += state_size * sizeof(double);
          }
        return bytes;
      },
      true);
    triangulation.save(settings.output_dir + "/checkpoint");
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::ofstream f(settings.output_dir + "/checkpoint.txt");
        f << increment << ' ' << std::setprecision(17) << t << ' ' << dt_previous << '\n';
        for (const auto &r : curve_rows)
          f << r << '\n';
        if (!f)
          throw std::runtime_error("cannot write " + settings.output_dir + "/checkpoint.txt");
      }
  }

  unsigned int
  JointProblem::load_checkpoint(double &t)
  {
    std::ifstream f(settings.output_dir + "/checkpoint.txt");
    unsigned int  increment = 0;
    if (!(f >> increment >> t >> dt_previous))
      throw std::runtime_error("no checkpoint in " + settings.output_dir);
    std::string line;
    std::getline(f, line);
    while (std::getline(f, line))
      if (!line.empty())
        curve_rows.push_back(line);

    triangulation.load(settings.output_dir + "/checkpoint");
    setup_system();
    parallel::distributed::SolutionTransfer<dim, PETScWrappers::MPI::Vector> transfer(
      dof_handler);
    std::vector<PETScWrappers::MPI::Vector *> vectors{&solution, &previous};
    transfer.deserialize(vectors);
    initialise_state();
    const unsigned int nq     = quadrature.size();
    const unsigned int handle = triangulation.register_data_attach(
      [](const typename Triangulation<dim>::cell_iterator &,
         const typename Triangulation<dim>::CellStatus) { return std::vector<char>(); },
      true);
    triangulation.notify_ready_to_unpack(
      handle,
      [this, nq](const typename Triangulation<dim>::cell_iterator &cell,
                 const typename Triangulation<dim>::CellStatus,
                 const boost::iterator_range<std::vector<char>::const_iterator> &range) {
        if (!in_layer(cell))
          return;
        if (static_cast<size_t>(range.size()) != nq * state_size * sizeof(double))
          throw std::runtime_error("a checkpoint's cell holds " +
                                   std::to_string(range.size()) + " bytes, not " +
                                   std::to_string(nq * state_size * sizeof(double)));
        const char *b = &*range.begin();
        for (auto &p : storage.get_data(cell))
          {
            std::memcpy(p->committed.data(), b, state_size * sizeof(double));
            b += state_size * sizeof(double);
          }
      });
    return increment;
  }

  void
  JointProblem::run()
  {
    make_grid();
    unsigned int done = 0;
    double       t    = 0;
    if (settings.restart)
      done = load_checkpoint(t);
    else
      {
        triangulation.refine_global(settings.refine);
        setup_system();
        initialise_state();
      }
    force_scale = pullout ? steel_yield * numbers::PI * bar_radius * bar_radius :
                            std::abs(settings.normal) * settings.length * settings.length;
    if (!(force_scale > 0))
      force_scale = settings.e_block * settings.length * settings.length * 1e-6;

    size_t n_points = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && in_layer(cell))
        n_points += quadrature.size();
    n_points = Utilities::MPI::sum(n_points, comm);
    pcout << "interlock_dealii: scene " << settings.scene << ", "
          << Utilities::MPI::n_mpi_processes(comm) << " processes, "
          << triangulation.n_global_active_cells() << " cells, " << dof_handler.n_dofs()
          << " dofs, " << n_points << " interface points, interlock " << interlock_version()
          << (settings.restart ? ", restarted after increment " + std::to_string(done) : "")
          << std::endl;

    Cost                       cost;
    const auto                 t_start = Clock::now();
    const double               dt_min  = 1e-6;
    const unsigned int         n_total =
      pullout ? settings.n_pull + settings.n_twist : 1 + settings.n_slip;
    PETScWrappers::MPI::Vector last(owned_dofs, comm);
    for (unsigned int increment = done + 1; increment <= n_total; ++increment)
      {
        const double t_end      = increment;
        double       dt         = t_end - t;
        unsigned int substeps   = 0, iterations = 0;
        while (t < t_end)
          {
            dt                    = std::min(dt, t_end - t);
            const double t_new    = (t_end - t - dt <= 1e-12) ? t_end : t + dt;
            last                  = solution;
            // In the slip phase the last substep's rate carries on: the layer's points start
            // Newton off the state they converged to (where a point that slid sits on its
            // friction cone to round-off, and its tangent would depend on the partition).
            const double phase = phase_start(t_new);
            if (dt_previous > 0 && t - dt_previous >= phase - 1e-12 && (pullout || phase > 0))
              {
                PETScWrappers::MPI::Vector rate = last;
                rate -= previous;
                solution.add((t_new - t) / dt_previous, rate);
              }
            current_normal        = settings.normal * normal_factor(t_new);
            set_platen(t_new);
            double     fraction   = 1;
            const bool converged  = newton(cost, iterations, fraction);
            // A converged iterate whose points ask for a cut is accepted all the same once the
            // step cannot be cut further (the request is about accuracy, not failure).
            const double cut = converged ? std::max(fraction, 0.01) : std::min(fraction, 0.5);
            if (!converged || (fraction < 1 && dt * cut >= dt_min))
              {
                if (!(fraction > 0))
                  throw std::runtime_error("a layer point refuses its input");
                if (settings.verbose > 0)
                  pcout << "    cut back by " << cut << " at t = " << t_new
                        << (converged ? " (a point asks for it)" : " (no convergence)")
                        << std::endl;
                solution = last;
                if (dt * cut < dt_min)
                  throw std::runtime_error("increment " + std::to_string(increment) +
                                           ": the step would fall below " +
                                           std::to_string(dt_min));
                dt *= cut;
                continue;
              }
            commit_state();
            previous    = last;
            dt_previous = t_new - t;
            t           = t_new;
            ++substeps;
            dt *= 2;
          }
        curve_rows.push_back(curve_row(increment, t, substeps, iterations));
        pcout << "  increment " << std::setw(3) << increment << ": " << substeps
              << " substeps, " << iterations << " Newton iterations" << std::endl;
        if (settings.vtu_every > 0 && increment % settings.vtu_every == 0)
          write_vtu(increment);
        if (settings.checkpoint_after == static_cast<int>(increment))
          {
            save_checkpoint(increment, t);
            pcout << "  checkpoint after increment " << increment << " in "
                  << settings.output_dir << std::endl;
            break;
          }
      }
    const double wall = std::chrono::duration<double>(Clock::now() - t_start).count();

    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::ofstream f(settings.output_dir + "/" + settings.curve);
        f << curve_header(pullout) << '\n';
        for (const auto &r : curve_rows)
          f << r << '\n';
        if (!f)
          throw std::runtime_error("cannot write the curve");
      }
    // The cost split per Newton iteration, the slowest process's; the memory per interface
    // point: its state in the cell storage (with the storage's pointer, its control block and
    // the vector's header) and its share of the batch (old and new state, separation,
    // traction, tangent, step fraction, status).
    const unsigned int its = std::max(1u, cost.iterations);
    const double       bytes =
      sizeof(double) * (3.0 * state_size + 3 + 3 + 9 + 1) + sizeof(int) + sizeof(PointState) +
      sizeof(std::shared_ptr<PointState>) + 2 * sizeof(void *);
    pcout << std::setprecision(4) << "cost: processes " << Utilities::MPI::n_mpi_processes(comm)
          << " points " << n_points << " dofs " << dof_handler.n_dofs() << " iterations "
          << cost.iterations << " law_s "
          << Utilities::MPI::max(cost.law, comm) / its << " assembly_s "
          << Utilities::MPI::max(cost.assembly, comm) / its << " solve_s "
          << Utilities::MPI::max(cost.solve, comm) / its << " law_cpu_s "
          << Utilities::MPI::max(cost.law_cpu, comm) / its << " assembly_cpu_s "
          << Utilities::MPI::max(cost.assembly_cpu, comm) / its << " solve_cpu_s "
          << Utilities::MPI::max(cost.solve_cpu, comm) / its << " wall_s " << wall
          << " bytes_per_point " << bytes << std::endl;
  }
} // namespace interlock_dealii

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      interlock_dealii::Settings settings;
      settings.parse(argc, argv);
      interlock_dealii::JointProblem problem(settings);
      problem.run();
    }
  catch (const std::exception &e)
    {
      std::cerr << "interlock_dealii: " << e.what() << std::endl;
      MPI_Abort(MPI_COMM_WORLD, 1);
    }
  return 0;
}
