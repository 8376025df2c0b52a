MODULE Logger
  ! limit is PERS of both tasks and written by neither: data written outside the loaded
  ! code (issue 28), each read a free choice as an input's is: shared.
  PERS num handshake := 0;
  PERS num status := 0;
  PERS num limit := 2;
  VAR num lines := 0;
  PERS bool ready{2} := [FALSE, FALSE];
  PROC main()
    WHILE lines < limit DO               ! SHARED
      lines := lines + 1;                ! LOCAL
      status := lines;                   ! SHARED
      handshake := 0;                    ! SHARED
      ready{2} := TRUE;                  ! SHARED
      Report lines;                      ! LOCAL
    ENDWHILE
  ENDPROC                                ! LOCAL
  PROC Report(num what)
    lines := what;                       ! LOCAL
  ENDPROC                                ! LOCAL
ENDMODULE
