/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for contact_system_at_rest() of
 * generated/na1/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive --checked-in
 * spec sha256: cfb213c907b133d8468816b35e2514e88b652abe0e80fc54ab4677cd1d4b1854
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_na1_contact_system_at_rest_ ## ID
#endif

#include <math.h>

#ifndef casadi_real
#define casadi_real double
#endif

#ifndef casadi_int
#define casadi_int long long int
#endif

/* Add prefix to internal symbols */
#define casadi_f0 CASADI_PREFIX(f0)
#define casadi_s0 CASADI_PREFIX(s0)
#define casadi_s1 CASADI_PREFIX(s1)
#define casadi_s2 CASADI_PREFIX(s2)
#define casadi_s3 CASADI_PREFIX(s3)
#define casadi_s4 CASADI_PREFIX(s4)
#define casadi_s5 CASADI_PREFIX(s5)
#define casadi_s6 CASADI_PREFIX(s6)
#define casadi_s7 CASADI_PREFIX(s7)
#define casadi_sq CASADI_PREFIX(sq)

/* Symbol visibility in DLLs */
#ifndef CASADI_SYMBOL_EXPORT
  #if defined(_WIN32) || defined(__WIN32__) || defined(__CYGWIN__)
    #if defined(STATIC_LINKED)
      #define CASADI_SYMBOL_EXPORT
    #else
      #define CASADI_SYMBOL_EXPORT __declspec(dllexport)
    #endif
  #elif defined(__GNUC__) && defined(GCC_HASCLASSVISIBILITY)
    #define CASADI_SYMBOL_EXPORT __attribute__ ((visibility ("default")))
  #else
    #define CASADI_SYMBOL_EXPORT
  #endif
#endif

casadi_real casadi_sq(casadi_real x) { return x*x;}

/* Configuration this file was compiled with */
CASADI_SYMBOL_EXPORT void snakecg_na1_contact_system_at_rest_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na1_contact_system_at_rest_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na1_contact_system_at_rest_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {4, 1, 1};
static const casadi_int casadi_s1[3] = {1, 1, 1};
static const casadi_int casadi_s2[3] = {3, 1, 1};
static const casadi_int casadi_s3[3] = {16, 1, 1};
static const casadi_int casadi_s4[3] = {2, 1, 1};
static const casadi_int casadi_s5[3] = {4, 4, 1};
static const casadi_int casadi_s6[3] = {3, 3, 1};
static const casadi_int casadi_s7[3] = {4, 3, 1};

/* snakecg_na1_contact_system_at_rest:(q[4],tau,q_obj[3],f_obj[3],K[16],contact_link[2],side,object_mass,object_inertia,rho[2],wheel_offset[2],contact_offset,object_distance,placed)->(M[4x4],delassus[3x3],b[3],qdd_free[4],a_obj_free[3],qdd_from_lam[4x3],a_obj_from_lam[3x3],gap,s) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44;
  a00=arg[4]? arg[4][8] : 0;
  if (res[0]!=0) res[0][0]=a00;
  a01=0.;
  if (res[0]!=0) res[0][1]=a01;
  a02=arg[4]? arg[4][10] : 0;
  a03=arg[0]? arg[0][2] : 0;
  a04=cos(a03);
  a05=arg[0]? arg[0][3] : 0;
  a06=sin(a05);
  a07=(a04*a06);
  a05=cos(a05);
  a03=sin(a03);
  a08=(a05*a03);
  a08=(a07+a08);
  a09=(a02*a08);
  a10=arg[4]? arg[4][9] : 0;
  a11=(a10*a03);
  a11=(a09+a11);
  a12=(-a11);
  if (res[0]!=0) res[0][2]=a12;
  a13=(-a09);
  if (res[0]!=0) res[0][3]=a13;
  if (res[0]!=0) res[0][4]=a01;
  if (res[0]!=0) res[0][5]=a00;
  a14=(a04*a05);
  a06=(a03*a06);
  a14=(a14-a06);
  a02=(a02*a14);
  a10=(a10*a04);
  a10=(a02+a10);
  if (res[0]!=0) res[0][6]=a10;
  if (res[0]!=0) res[0][7]=a02;
  if (res[0]!=0) res[0][8]=a12;
  if (res[0]!=0) res[0][9]=a10;
  a12=(a14*a04);
  a06=(a08*a03);
  a12=(a12+a06);
  a06=arg[4]? arg[4][12] : 0;
  a12=(a12*a06);
  a06=arg[4]? arg[4][14] : 0;
  a06=(a12+a06);
  a15=arg[4]? arg[4][15] : 0;
  a12=(a12+a15);
  a06=(a06+a12);
  if (res[0]!=0) res[0][10]=a06;
  if (res[0]!=0) res[0][11]=a12;
  if (res[0]!=0) res[0][12]=a13;
  if (res[0]!=0) res[0][13]=a02;
  if (res[0]!=0) res[0][14]=a12;
  if (res[0]!=0) res[0][15]=a15;
  a13=arg[5]? arg[5][0] : 0;
  a16=(a13*a03);
  a17=arg[5]? arg[5][1] : 0;
  a05=(a03*a05);
  a05=(a05+a07);
  a07=(a17*a05);
  a16=(a16+a07);
  a07=arg[6]? arg[6][0] : 0;
  a18=(a16*a07);
  a19=(a13+a17);
  a20=(a18*a19);
  a21=(a20/a00);
  a11=(a11/a00);
  a22=arg[0]? arg[0][1] : 0;
  a23=arg[4]? arg[4][2] : 0;
  a24=arg[4]? arg[4][6] : 0;
  a23=(a23-a24);
  a25=(a23*a03);
  a25=(a22+a25);
  a26=arg[4]? arg[4][7] : 0;
  a08=(a08*a26);
  a25=(a25+a08);
  a27=(a22-a25);
  a28=(a17*a27);
  a28=(a18*a28);
  a29=(a13*a04);
  a30=(a17*a14);
  a29=(a29+a30);
  a30=(a29*a07);
  a31=arg[0]? arg[0][0] : 0;
  a23=(a04*a23);
  a23=(a31+a23);
  a32=(a14*a26);
  a23=(a23+a32);
  a33=(a23-a31);
  a34=(a17*a33);
  a34=(a30*a34);
  a28=(a28-a34);
  a24=(a24*a13);
  a26=(a26*a17);
  a24=(a24+a26);
  a26=(a07*a24);
  a34=casadi_sq(a16);
  a34=(a26*a34);
  a35=casadi_sq(a29);
  a26=(a26*a35);
  a34=(a34+a26);
  a26=1.;
  a35=arg[13]? arg[13][0] : 0;
  a26=(a26-a35);
  a36=arg[2]? arg[2][2] : 0;
  a37=cos(a36);
  a37=(a26*a37);
  a38=(a35*a29);
  a37=(a37+a38);
  a38=arg[9]? arg[9][1] : 0;
  a38=(a26*a38);
  a39=arg[12]? arg[12][0] : 0;
  a40=(a07*a39);
  a40=(a35*a40);
  a38=(a38-a40);
  a40=(a37*a38);
  a36=sin(a36);
  a36=(a26*a36);
  a41=(a35*a16);
  a36=(a36+a41);
  a41=arg[9]? arg[9][0] : 0;
  a41=(a26*a41);
  a42=(a36*a41);
  a40=(a40+a42);
  a42=arg[2]? arg[2][1] : 0;
  a42=(a26*a42);
  a22=(a22*a13);
  a25=(a25*a17);
  a22=(a22+a25);
  a25=arg[11]? arg[11][0] : 0;
  a25=(a25-a24);
  a43=(a25*a16);
  a43=(a22+a43);
  a44=(a07*a29);
  a44=(a39*a44);
  a43=(a43+a44);
  a43=(a35*a43);
  a42=(a42+a43);
  a42=(a40+a42);
  a43=(a16*a24);
  a42=(a42+a43);
  a42=(a42-a22);
  a22=(a18*a42);
  a34=(a34-a22);
  a37=(a37*a41);
  a36=(a36*a38);
  a37=(a37-a36);
  a36=arg[2]? arg[2][0] : 0;
  a26=(a26*a36);
  a31=(a31*a13);
  a23=(a23*a17);
  a31=(a31+a23);
  a25=(a25*a29);
  a25=(a31+a25);
  a23=(a07*a16);
  a39=(a39*a23);
  a25=(a25-a39);
  a35=(a35*a25);
  a26=(a26+a35);
  a26=(a37+a26);
  a24=(a29*a24);
  a26=(a26+a24);
  a26=(a26-a31);
  a31=(a30*a26);
  a34=(a34-a31);
  a31=(a34*a19);
  a28=(a28+a31);
  a31=(a11*a20);
  a31=(a28+a31);
  a10=(a10/a00);
  a19=(a30*a19);
  a24=(a10*a19);
  a31=(a31+a24);
  a24=casadi_sq(a11);
  a24=(a24*a00);
  a06=(a06-a24);
  a24=casadi_sq(a10);
  a24=(a24*a00);
  a06=(a06-a24);
  a24=(a31/a06);
  a09=(a09/a00);
  a35=(a09*a11);
  a35=(a35*a00);
  a12=(a12-a35);
  a02=(a02/a00);
  a35=(a02*a10);
  a35=(a35*a00);
  a12=(a12-a35);
  a12=(a12/a06);
  a34=(a34*a17);
  a35=(a17*a08);
  a35=(a18*a35);
  a17=(a17*a32);
  a17=(a30*a17);
  a35=(a35+a17);
  a34=(a34-a35);
  a35=(a09*a20);
  a35=(a34+a35);
  a17=(a02*a19);
  a35=(a35+a17);
  a31=(a12*a31);
  a35=(a35-a31);
  a31=casadi_sq(a09);
  a31=(a31*a00);
  a15=(a15-a31);
  a31=casadi_sq(a02);
  a31=(a31*a00);
  a15=(a15-a31);
  a31=casadi_sq(a12);
  a31=(a31*a06);
  a15=(a15-a31);
  a35=(a35/a15);
  a31=(a12*a35);
  a24=(a24-a31);
  a31=(a11*a24);
  a21=(a21+a31);
  a31=(a09*a35);
  a21=(a21+a31);
  a31=(a20*a21);
  a17=(a19/a00);
  a25=(a10*a24);
  a17=(a17+a25);
  a25=(a02*a35);
  a17=(a17+a25);
  a25=(a19*a17);
  a31=(a31+a25);
  a25=(a28*a24);
  a31=(a31+a25);
  a25=(a34*a35);
  a31=(a31+a25);
  a25=arg[7]? arg[7][0] : 0;
  a39=(a18/a25);
  a23=(a18*a39);
  a13=(a30/a25);
  a36=(a30*a13);
  a23=(a23+a36);
  a37=(a29*a37);
  a37=(a37*a07);
  a40=(a18*a40);
  a37=(a37+a40);
  a40=arg[8]? arg[8][0] : 0;
  a36=(a37/a40);
  a38=(a37*a36);
  a23=(a23+a38);
  a31=(a31+a23);
  if (res[1]!=0) res[1][0]=a31;
  a31=arg[10]? arg[10][0] : 0;
  a23=(a31*a24);
  a38=(a03*a21);
  a41=(a04*a17);
  a38=(a38+a41);
  a23=(a23-a38);
  if (res[1]!=0) res[1][1]=a23;
  a33=(a14*a33);
  a27=(a05*a27);
  a33=(a33-a27);
  a27=arg[10]? arg[10][1] : 0;
  a33=(a33+a27);
  a23=(a33*a24);
  a38=(a05*a21);
  a41=(a14*a17);
  a38=(a38+a41);
  a23=(a23-a38);
  a08=(a05*a08);
  a32=(a14*a32);
  a08=(a08+a32);
  a08=(a08+a27);
  a27=(a08*a35);
  a23=(a23+a27);
  if (res[1]!=0) res[1][2]=a23;
  a23=(a11*a03);
  a23=(a31-a23);
  a27=(a10*a04);
  a23=(a23-a27);
  a27=(a23/a06);
  a32=(a09*a03);
  a38=(a02*a04);
  a32=(a32+a38);
  a23=(a12*a23);
  a32=(a32+a23);
  a32=(a32/a15);
  a23=(a12*a32);
  a27=(a27+a23);
  a23=(a11*a27);
  a38=(a03/a00);
  a23=(a23-a38);
  a38=(a09*a32);
  a23=(a23-a38);
  a38=(a20*a23);
  a41=(a04/a00);
  a22=(a10*a27);
  a41=(a41-a22);
  a22=(a02*a32);
  a41=(a41+a22);
  a22=(a19*a41);
  a38=(a38-a22);
  a22=(a28*a27);
  a38=(a38+a22);
  a22=(a34*a32);
  a38=(a38-a22);
  if (res[1]!=0) res[1][3]=a38;
  a38=(a04*a41);
  a22=(a03*a23);
  a38=(a38-a22);
  a22=(a31*a27);
  a38=(a38+a22);
  if (res[1]!=0) res[1][4]=a38;
  a38=(a14*a41);
  a22=(a05*a23);
  a38=(a38-a22);
  a22=(a33*a27);
  a38=(a38+a22);
  a22=(a08*a32);
  a38=(a38-a22);
  if (res[1]!=0) res[1][5]=a38;
  a38=(a11*a05);
  a38=(a33-a38);
  a22=(a10*a14);
  a38=(a38-a22);
  a06=(a38/a06);
  a22=(a09*a05);
  a22=(a08-a22);
  a43=(a02*a14);
  a22=(a22-a43);
  a38=(a12*a38);
  a22=(a22-a38);
  a22=(a22/a15);
  a38=(a12*a22);
  a06=(a06-a38);
  a38=(a11*a06);
  a43=(a05/a00);
  a38=(a38-a43);
  a43=(a09*a22);
  a38=(a38+a43);
  a43=(a20*a38);
  a00=(a14/a00);
  a44=(a10*a06);
  a00=(a00-a44);
  a44=(a02*a22);
  a00=(a00-a44);
  a44=(a19*a00);
  a43=(a43-a44);
  a44=(a28*a06);
  a43=(a43+a44);
  a44=(a34*a22);
  a43=(a43+a44);
  if (res[1]!=0) res[1][6]=a43;
  a43=(a04*a00);
  a44=(a03*a38);
  a43=(a43-a44);
  a44=(a31*a06);
  a43=(a43+a44);
  if (res[1]!=0) res[1][7]=a43;
  a43=(a14*a00);
  a44=(a05*a38);
  a43=(a43-a44);
  a44=(a33*a06);
  a43=(a43+a44);
  a44=(a08*a22);
  a43=(a43+a44);
  if (res[1]!=0) res[1][8]=a43;
  a43=arg[1]? arg[1][0] : 0;
  a43=(a43/a15);
  a09=(a09*a43);
  a12=(a12*a43);
  a11=(a11*a12);
  a09=(a09-a11);
  a20=(a20*a09);
  a10=(a10*a12);
  a02=(a02*a43);
  a10=(a10-a02);
  a19=(a19*a10);
  a20=(a20-a19);
  a28=(a28*a12);
  a20=(a20-a28);
  a34=(a34*a43);
  a20=(a20+a34);
  a34=arg[3]? arg[3][1] : 0;
  a34=(a34/a25);
  a28=(a30*a34);
  a19=arg[3]? arg[3][0] : 0;
  a19=(a19/a25);
  a18=(a18*a19);
  a28=(a28-a18);
  a18=arg[3]? arg[3][2] : 0;
  a18=(a18/a40);
  a37=(a37*a18);
  a28=(a28+a37);
  a20=(a20+a28);
  if (res[2]!=0) res[2][0]=a20;
  a04=(a04*a10);
  a03=(a03*a09);
  a04=(a04-a03);
  a31=(a31*a12);
  a04=(a04-a31);
  if (res[2]!=0) res[2][1]=a04;
  a14=(a14*a10);
  a05=(a05*a09);
  a14=(a14-a05);
  a33=(a33*a12);
  a14=(a14-a33);
  a08=(a08*a43);
  a14=(a14+a08);
  if (res[2]!=0) res[2][2]=a14;
  if (res[3]!=0) res[3][0]=a09;
  if (res[3]!=0) res[3][1]=a10;
  a12=(-a12);
  if (res[3]!=0) res[3][2]=a12;
  if (res[3]!=0) res[3][3]=a43;
  if (res[4]!=0) res[4][0]=a19;
  if (res[4]!=0) res[4][1]=a34;
  if (res[4]!=0) res[4][2]=a18;
  if (res[5]!=0) res[5][0]=a21;
  a17=(-a17);
  if (res[5]!=0) res[5][1]=a17;
  if (res[5]!=0) res[5][2]=a24;
  if (res[5]!=0) res[5][3]=a35;
  if (res[5]!=0) res[5][4]=a23;
  if (res[5]!=0) res[5][5]=a41;
  if (res[5]!=0) res[5][6]=a27;
  a32=(-a32);
  if (res[5]!=0) res[5][7]=a32;
  if (res[5]!=0) res[5][8]=a38;
  if (res[5]!=0) res[5][9]=a00;
  if (res[5]!=0) res[5][10]=a06;
  if (res[5]!=0) res[5][11]=a22;
  a39=(-a39);
  if (res[6]!=0) res[6][0]=a39;
  if (res[6]!=0) res[6][1]=a13;
  if (res[6]!=0) res[6][2]=a36;
  if (res[6]!=0) res[6][3]=a01;
  if (res[6]!=0) res[6][4]=a01;
  if (res[6]!=0) res[6][5]=a01;
  if (res[6]!=0) res[6][6]=a01;
  if (res[6]!=0) res[6][7]=a01;
  if (res[6]!=0) res[6][8]=a01;
  a30=(a42*a30);
  a01=(a16*a26);
  a01=(a01*a07);
  a30=(a30-a01);
  if (res[7]!=0) res[7][0]=a30;
  a16=(a16*a42);
  a29=(a29*a26);
  a16=(a16+a29);
  if (res[8]!=0) res[8][0]=a16;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na1_contact_system_at_rest(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na1_contact_system_at_rest_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na1_contact_system_at_rest_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na1_contact_system_at_rest_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na1_contact_system_at_rest_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na1_contact_system_at_rest_n_in(void) { return 14;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na1_contact_system_at_rest_n_out(void) { return 9;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na1_contact_system_at_rest_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na1_contact_system_at_rest_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "tau";
    case 2: return "q_obj";
    case 3: return "f_obj";
    case 4: return "K";
    case 5: return "contact_link";
    case 6: return "side";
    case 7: return "object_mass";
    case 8: return "object_inertia";
    case 9: return "rho";
    case 10: return "wheel_offset";
    case 11: return "contact_offset";
    case 12: return "object_distance";
    case 13: return "placed";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na1_contact_system_at_rest_name_out(casadi_int i) {
  switch (i) {
    case 0: return "M";
    case 1: return "delassus";
    case 2: return "b";
    case 3: return "qdd_free";
    case 4: return "a_obj_free";
    case 5: return "qdd_from_lam";
    case 6: return "a_obj_from_lam";
    case 7: return "gap";
    case 8: return "s";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na1_contact_system_at_rest_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s2;
    case 4: return casadi_s3;
    case 5: return casadi_s4;
    case 6: return casadi_s1;
    case 7: return casadi_s1;
    case 8: return casadi_s1;
    case 9: return casadi_s4;
    case 10: return casadi_s4;
    case 11: return casadi_s1;
    case 12: return casadi_s1;
    case 13: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na1_contact_system_at_rest_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s5;
    case 1: return casadi_s6;
    case 2: return casadi_s2;
    case 3: return casadi_s0;
    case 4: return casadi_s2;
    case 5: return casadi_s7;
    case 6: return casadi_s6;
    case 7: return casadi_s1;
    case 8: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na1_contact_system_at_rest_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 14;
  if (sz_res) *sz_res = 9;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na1_contact_system_at_rest_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 14*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 9*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}



/* ------------------------------------------------------------------------------------------
 * GENERATED FILE - DO NOT EDIT. Batched drivers rendered from derive/templates/batch.c.j2.
 * snakecg's counterpart of CasADi's Function.map(n, "serial"): one loop in C over n samples,
 * reading inputs in place (input k of sample i at arg[k] + i * stride[k]; stride 0 broadcasts)
 * and writing dense column-major outputs contiguously (output k of sample i at
 * res[k] + i * nnz_out(k)). Returns 0 on success, the failing sample + 1 otherwise, -1 when out of memory.
 * ---------------------------------------------------------------------------------------- */
#include <stdlib.h>

CASADI_SYMBOL_EXPORT int snakecg_na1_batch_contact_system_at_rest(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[14];
  casadi_real* r[9];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 46);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 14; ++k) a[k] = 0;
  for (k = 0; k < 9; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    a[2] = arg[2] + i * stride[2];
    a[3] = arg[3] + i * stride[3];
    a[4] = arg[4] + i * stride[4];
    a[5] = arg[5] + i * stride[5];
    a[6] = arg[6] + i * stride[6];
    a[7] = arg[7] + i * stride[7];
    a[8] = arg[8] + i * stride[8];
    a[9] = arg[9] + i * stride[9];
    a[10] = arg[10] + i * stride[10];
    a[11] = arg[11] + i * stride[11];
    a[12] = arg[12] + i * stride[12];
    a[13] = arg[13] + i * stride[13];
    r[0] = res[0] + i * 16;
    r[1] = res[1] + i * 9;
    r[2] = res[2] + i * 3;
    r[3] = res[3] + i * 4;
    r[4] = res[4] + i * 3;
    r[5] = res[5] + i * 12;
    r[6] = res[6] + i * 9;
    r[7] = res[7] + i * 1;
    r[8] = res[8] + i * 1;
    if (snakecg_na1_contact_system_at_rest(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
