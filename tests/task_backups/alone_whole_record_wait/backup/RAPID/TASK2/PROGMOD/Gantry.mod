MODULE Gantry
    ! Written for the test (issue 28): the gantry answers robot 1 through hs.
    RECORD handshake
        bool robot;
        bool gantry;
        num station;
    ENDRECORD
    PERS handshake hs := [FALSE, FALSE, 0];

    PROC main()
        WHILE TRUE DO
            WaitUntil hs.robot;
            hs.station := 1;
            hs.gantry := TRUE;
            WaitUntil NOT hs.robot;
            hs.station := 2;
            hs.gantry := FALSE;
        ENDWHILE
    ENDPROC
ENDMODULE
