MODULE Plc
    ! The PLC task grants the shared zone to one robot at a time, and only
    ! with the cell door closed and locked: it locks the door first, then
    ! reads it (a locked door cannot open), and unlocks it when neither robot
    ! holds the zone.  When both robots ask, the one that did not have the
    ! zone last gets it (turn), so neither waits for ever.
    PERS bool req1 := FALSE;
    PERS bool grant1 := FALSE;
    PERS bool req2 := FALSE;
    PERS bool grant2 := FALSE;
    VAR num turn := 1;

    PROC plc_main()
        WHILE TRUE DO
            IF (NOT grant1) AND (NOT grant2) AND (req1 OR req2) THEN
                SetDO doDoorLock, 1;
                IF diDoorOpen = 0 THEN
                    IF req1 AND (turn = 1 OR NOT req2) THEN
                        grant1 := TRUE;
                        turn := 2;
                    ELSE
                        grant2 := TRUE;
                        turn := 1;
                    ENDIF
                ENDIF
            ENDIF
            IF grant1 AND NOT req1 grant1 := FALSE;
            IF grant2 AND NOT req2 grant2 := FALSE;
            IF (NOT grant1) AND (NOT grant2) SetDO doDoorLock, 0;
        ENDWHILE
    ENDPROC
ENDMODULE
