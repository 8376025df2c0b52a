MODULE num_float32_fraction
  ! Tests: num is IEEE single precision. In float32, 0.1 + 0.2 equals 0.3
  ! and 1 + 1E-8 equals 1 (both are FALSE in double precision), so these
  ! comparisons tell float32 arithmetic apart from float64.
  PROC main()
    VAR num a := 0.1;
    VAR num b := 0.2;
    VAR num c := 0.3;
    VAR num one := 1;
    VAR num tiny := 1E-8;
    TPWrite "0.1+0.2=0.3 " \Bool:=a + b = c;
    TPWrite "1+1E-8=1 " \Bool:=one + tiny = one;
  ENDPROC
ENDMODULE
