MODULE a_main
  ! Tests: global (non-LOCAL) data and routines of one module are visible in
  ! the other modules of the task.
  PROC main()
    Bump 3;
    Bump 4;
    TPWrite "counter=" \Num:=counter;
    TPWrite "limit=" \Num:=LIMIT;
  ENDPROC
ENDMODULE
