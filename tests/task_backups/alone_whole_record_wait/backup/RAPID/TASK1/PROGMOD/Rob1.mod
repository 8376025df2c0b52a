MODULE Rob1
    ! Written for the test (issue 28): robot 1 and the gantry each set their part of hs.
    RECORD handshake
        bool robot;
        bool gantry;
        num station;
    ENDRECORD
    PERS handshake hs := [FALSE, FALSE, 0];

    PROC main()
        WHILE TRUE DO
            hs.robot := TRUE;
            WaitUntil hs = [TRUE, TRUE, 1];
            hs.robot := FALSE;
            WHILE hs <> [FALSE, FALSE, 2] DO
                WaitTime 0.1;
            ENDWHILE
        ENDWHILE
    ENDPROC
ENDMODULE
