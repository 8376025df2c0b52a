MODULE unary_minus
  ! Tests: unary minus on literals, variables and parenthesised expressions;
  ! -a * b equals -(a * b); unary minus after * is accepted.
  PROC main()
    VAR num a := 2;
    VAR num b := 3;
    TPWrite "-a*b=" \Num:=-a * b;
    TPWrite "-(a-b)=" \Num:=-(a - b);
    TPWrite "b*-a=" \Num:=b * -a;
    TPWrite "--" \Num:=-(-a);
  ENDPROC
ENDMODULE
