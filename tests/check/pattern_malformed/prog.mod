MODULE Simple
    ! A valid program; the bad input of this case is elsewhere.
    VAR num count := 0;
    VAR bool done := FALSE;

    PROC main()
        count := count + 1;
        done := TRUE;
    ENDPROC
ENDMODULE
