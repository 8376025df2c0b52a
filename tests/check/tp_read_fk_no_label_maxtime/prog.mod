MODULE TpReadFkNoLabelMaxTime
    ! A message without keys that \MaxTime ends: ERR_TP_MAXTIME, handled here.
    VAR num key := 0;
    VAR bool timed_out := FALSE;

    PROC main()
        TPReadFK key, "Door open", stEmpty, stEmpty, stEmpty, stEmpty, stEmpty \MaxTime:=5;
    ERROR
        IF ERRNO = ERR_TP_MAXTIME THEN
            timed_out := TRUE;
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
