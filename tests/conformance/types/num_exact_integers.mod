MODULE num_exact_integers
  ! Tests: integer arithmetic on num stays exact inside the documented exact
  ! range (up to 8388608): sums and differences of large integers compare
  ! equal exactly. (Compared, not printed: how 7-digit integers print is not
  ! documented.)
  PROC main()
    VAR num a := 4000000;
    VAR num b := 4388608;
    VAR num c;
    c := a + b;
    TPWrite "sum " \Bool:=c = 8388608;
    TPWrite "exact " \Bool:=c - b = a;
    c := -c;
    TPWrite "neg " \Bool:=c + 8388608 = 0;
    TPWrite "small=" \Num:=c + 8388600;
  ENDPROC
ENDMODULE
