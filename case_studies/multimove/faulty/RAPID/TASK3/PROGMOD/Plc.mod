MODULE Plc
    ! The PLC task guards the cell door: it grants a robot's request only
    ! with the door closed and locked (it locks the door first, then reads
    ! it: a locked door cannot open), and unlocks it when neither robot holds
    ! a grant.  Keeping the robots apart is left to the robots (zone_busy).
    PERS bool req1 := FALSE;
    PERS bool grant1 := FALSE;
    PERS bool req2 := FALSE;
    PERS bool grant2 := FALSE;

    PROC plc_main()
        WHILE TRUE DO
            IF (req1 AND NOT grant1) OR (req2 AND NOT grant2) THEN
                SetDO doDoorLock, 1;
                IF diDoorOpen = 0 THEN
                    IF req1 grant1 := TRUE;
                    IF req2 grant2 := TRUE;
                ENDIF
            ENDIF
            IF grant1 AND NOT req1 grant1 := FALSE;
            IF grant2 AND NOT req2 grant2 := FALSE;
            IF (NOT grant1) AND (NOT grant2) SetDO doDoorLock, 0;
        ENDWHILE
    ENDPROC
ENDMODULE
