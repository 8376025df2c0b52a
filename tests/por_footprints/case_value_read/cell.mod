MODULE Cell
  ! The partner reads code only as a value of a TEST's CASE: still a read by another
  ! task, so the write of code depends on the partner's steps.
  PERS num code := 0;
  PROC main()
    code := 1;                           ! SHARED
  ENDPROC
ENDMODULE
