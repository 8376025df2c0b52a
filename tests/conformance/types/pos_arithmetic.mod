MODULE pos_arithmetic
  ! Tests: pos + pos and pos - pos work component-wise, num * pos scales.
  PROC main()
    VAR pos a := [1, 2, 3];
    VAR pos b := [4, 5, 6];
    TPWrite "a+b=" \Pos:=a + b;
    TPWrite "b-a=" \Pos:=b - a;
    TPWrite "2*a=" \Pos:=2 * a;
  ENDPROC
ENDMODULE
