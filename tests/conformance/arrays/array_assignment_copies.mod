MODULE array_assignment_copies
  ! Tests: assigning a whole array copies its elements; later changes to the
  ! copy do not affect the source.
  PROC main()
    VAR num a{3} := [1, 2, 3];
    VAR num b{3};
    b := a;
    b{1} := 9;
    TPWrite "a{1}=" \Num:=a{1};
    TPWrite "b{1}=" \Num:=b{1};
    TPWrite "b{3}=" \Num:=b{3};
  ENDPROC
ENDMODULE
