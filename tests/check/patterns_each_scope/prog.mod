MODULE Events
    ! Events in a fixed order, each true in one state and false in the next:
    ! p, q, s, p, r, s; then main ends (the last state, all false, repeats).
    VAR bool p := FALSE;
    VAR bool q := FALSE;
    VAR bool r := FALSE;
    VAR bool s := FALSE;

    PROC main()
        p := TRUE;
        p := FALSE;
        q := TRUE;
        q := FALSE;
        s := TRUE;
        s := FALSE;
        p := TRUE;
        p := FALSE;
        r := TRUE;
        r := FALSE;
        s := TRUE;
        s := FALSE;
    ENDPROC
ENDMODULE
