//! Scenarios with rods for the tests of `rods.rs`, `rod_refusals.rs`,
//! `rod_channels.rs` and `pinned_rods.rs`: a TOML free rod with two
//! threads and a MoorDyn deck of a free body carrying a rod.

use super::text;

/// A horizontal free rod (MoorDyn's `rod_tests/AddedMass.txt`: 2 m
/// long, 0.5 m across, 100 kg/m, Ca 1, every other coefficient 0) at
/// z = -10 m in still water, with a light thread (1 m, 1 mm, 0.01 kg/m,
/// no drag or added mass) hanging from each end; `analysis` the
/// `[analysis]` body.
pub fn rising_rod(analysis: &str) -> String {
    format!(
        "title = \"rising rod\"\n[water]\ndepth = 50.0\ndensity = 1025.0\n\
         [[line_types]]\nname = \"thread\"\ndiameter = 0.001\nmass_per_length = 0.01\nea = 1.0e3\n\
         [[rod_types]]\nname = \"can\"\ndiameter = 0.5\nmass_per_length = 100.0\nca = 1.0\n\
         [[rods]]\nid = 7\ntype = \"free\"\nrod_type = \"can\"\nend_a = [-1.0, 0.0, -10.0]\n\
         end_b = [1.0, 0.0, -10.0]\nsegments = 4\n\
         [[points]]\nid = 1\ntype = \"rod\"\nrod = 7\nend = \"A\"\n\
         [[points]]\nid = 2\ntype = \"rod\"\nrod = 7\nend = \"B\"\n\
         [[lines]]\nid = 1\ntype = \"thread\"\nlength = 1.0\nelements = 2\na = 1\n\
         [[lines]]\nid = 2\ntype = \"thread\"\nlength = 1.0\nelements = 2\na = 2\n\
         [analysis]\n{analysis}\n"
    )
}

/// A free body carrying a rod (`Body1`, 4 m, 100 kg/m, 0.5 m) hung from
/// the surface by lines at the rod's ends, one line running through a
/// free rod of zero length (`NumSegs` 0, a point); `rod_outputs` the
/// zero-length rod's RodOutputs, `ei` the ropes' EI.
pub fn body_rod_deck(rod_outputs: &str, ei: &str) -> String {
    format!(
        "--------------------- MoorDyn Input File ---------------------------------------
A free body carrying a rod, hung by lines at the rod's ends
----------------------- LINE TYPES ------------------------------------------
TypeName Diam  Mass/m   EA         BA/-zeta EI      Cd  Ca  CdAx CaAx
(name)   (m)   (kg/m)   (N)        (N-s/-)  (N-m^2) (-) (-) (-)  (-)
rope     0.05  10.0     1.0E8      -0.5     {ei}    1.2 1.0 0.1  0.0
---------------------- ROD TYPES -----------------------------------------------
TypeName      Diam     Mass/m    Cd     Ca      CdEnd    CaEnd
(name)        (m)      (kg/m)    (-)    (-)     (-)      (-)
can           0.5      100       1.2    1.0     0.6      0.5
conn          0.1      5         1.0    1.0     1.0      1.0
---------------------------- BODIES -----------------------------------------------------
ID   Attachment  X0     Y0    Z0     r0      p0     y0     Mass  CG*   I*      Volume   CdA*    Ca
(#)     (-)      (m)    (m)   (m)   (deg)   (deg)  (deg)   (kg)  (m)  (kg-m^2)  (m^3)   (m^2)   (-)
1      Free      0.0    0    -20.0   0       0      0      1000   0    1000     0        0       0
---------------------- RODS ----------------------------------------------------
ID   RodType   Attachment  Xa    Ya    Za    Xb    Yb    Zb   NumSegs RodOutputs
(#)  (name)     (#/key)    (m)   (m)   (m)   (m)   (m)   (m)  (-)     (-)
1    can       Body1       -2    0     0     2     0     0    4       -
2    conn      Free        15    0     -10   15    0     -10  0       {rod_outputs}
---------------------- POINTS --------------------------------------------------
ID    Type      X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)       (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed     -30     0       0       0      0       0      0
2     Fixed      30     0       0       0      0       0      0
---------------------- LINES ---------------------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     rope       1        R1A       36        12      -
2     rope       2        R2A       18        6       -
3     rope       r2b      Rod1B     20        6       -
---------------------- OPTIONS -------------------------------------------------
0.002         dtM                  time step (s)
100           WtrDpth              water depth (m)
------------------------- need this line --------------------------------------
"
    )
}

pub fn text_of(o: &std::process::Output) -> String {
    let (so, se) = text(o);
    format!("{so}{se}")
}
