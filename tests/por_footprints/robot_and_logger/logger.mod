MODULE Logger
  ! limit is PERS of both tasks and written by neither: reading it is local.
  PERS num handshake := 0;
  PERS num status := 0;
  PERS num limit := 2;
  VAR num lines := 0;
  PROC main()
    WHILE lines < limit DO               ! LOCAL
      lines := lines + 1;                ! LOCAL
      status := lines;                   ! SHARED
      handshake := 0;                    ! SHARED
      Report lines;                      ! SHARED
    ENDWHILE
  ENDPROC                                ! LOCAL
  PROC Report(num what)
    lines := what;                       ! LOCAL
  ENDPROC                                ! LOCAL
ENDMODULE
