MODULE num_exact_integers
  ! Tests: integer arithmetic on num stays exact inside the documented exact
  ! range (up to 8388608): sums of large integers compare equal exactly and
  ! print without decimals.
  PROC main()
    VAR num a := 4000000;
    VAR num b := 4388608;
    VAR num c;
    c := a + b;
    TPWrite "c=" \Num:=c;
    TPWrite "exact " \Bool:=c - b = a;
    c := -c;
    TPWrite "neg=" \Num:=c;
  ENDPROC
ENDMODULE
