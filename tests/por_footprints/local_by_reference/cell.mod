MODULE Cell
  ! A routine's own VAR passed by reference (reduction/syntax_footprint.py: the root
  ! of the argument is the calling routine's datum).  Each line ends with its footprint.
  PERS num counter := 0;
  PROC main()
    VAR num mine := 0;
    FOR i FROM 1 TO 2 DO                 ! LOCAL
      Bump mine;                         ! LOCAL
      counter := mine;                   ! SHARED
    ENDFOR
  ENDPROC                                ! LOCAL
  ! only a routine's own datum is passed: its writes are the task's own
  PROC Bump(INOUT num value)
    value := value MOD 4 + 1;            ! LOCAL
  ENDPROC                                ! LOCAL
ENDMODULE
