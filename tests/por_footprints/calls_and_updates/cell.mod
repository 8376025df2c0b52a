MODULE Cell
  ! Instructions judged from their syntax (reduction/syntax_footprint.py): element and
  ! component writes, numeric updates, calls with arguments, functions, TPWrite,
  ! WaitTime.  Each line ends with its footprint.
  PERS num counter := 0;
  PERS num handed := 0;
  VAR num parts := 0;
  VAR num shown := 0;
  VAR num slots{3} := [0, 0, 0];
  VAR pos spot := [0, 0, 0];
  VAR string text := "";
  PROC main()
    FOR i FROM 1 TO 2 DO                 ! LOCAL
      slots{i} := parts;                 ! LOCAL
      slots{i} := counter;               ! SHARED
      spot.x := spot.x + 1;              ! LOCAL
      Incr parts;                        ! LOCAL
      Incr shown;                        ! VISIBLE
      Incr counter;                      ! SHARED
      Add parts, Abs(spot.x - 2);        ! LOCAL
      text := NumToStr(parts, 0);        ! LOCAL
      Bump parts;                        ! LOCAL
      Tally counter;                     ! SHARED
      Tally parts;                       ! LOCAL
      Show parts;                        ! LOCAL
      Show handed;                       ! SHARED
      parts := Half(parts);              ! LOCAL
      IF Half(parts) > 1 parts := 0;     ! LOCAL
      TPWrite "parts ", \Num:=parts;     ! LOCAL
      TPWrite "handed ", \Num:=handed;   ! SHARED
      WaitTime 0.1;                      ! LOCAL
    ENDFOR
  ENDPROC                                ! LOCAL
  ! only the cell's own data is passed: its writes are the cell's own
  PROC Bump(INOUT num value)
    value := value MOD 4 + 1;            ! LOCAL
  ENDPROC                                ! LOCAL
  ! the shared counter is passed too: its writes and reads are shared
  PROC Tally(INOUT num value)
    IF value > 2 THEN                    ! SHARED
      value := 0;                        ! SHARED
    ENDIF
  ENDPROC                                ! LOCAL
  PROC Show(num value)
    shown := value;                      ! VISIBLE
  ENDPROC                                ! LOCAL
  FUNC num Half(num value)
    RETURN value DIV 2;                  ! LOCAL
  ENDFUNC
ENDMODULE
