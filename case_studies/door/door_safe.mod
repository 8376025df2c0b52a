MODULE DoorCell
    ! A pick-and-place cell behind a safety door with guard locking, and an
    ! operator station guarded by a light curtain.  The robot must never move
    ! while the door is open.  Correct version: lock the door first, then
    ! check that it is closed; a locked, closed door cannot open.

    VAR robtarget home := [[400, 0, 700], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR robtarget pick := [[600, 300, 200], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR robtarget station := [[600, -300, 200], [0, 0, 1, 0], [-1, 0, -1, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR speeddata v := [1000, 500, 5000, 1000];
    VAR zonedata zone := [FALSE, 10, 15, 15, 1.5, 15, 1.5];
    PERS tooldata gripper := [TRUE, [[0, 0, 150], [1, 0, 0, 0]], [1.5, [0, 0, 60], [1, 0, 0, 0], 0, 0, 0]];

    VAR signaldi door_closed;    ! door switch, 1 = closed
    VAR signaldi curtain_clear;  ! light curtain at the operator station, 1 = nobody reaches in
    VAR signaldo door_lock;      ! guard locking, 1 = hold the door shut

    PROC main()
        AliasIO "DOOR_CLOSED", door_closed;
        AliasIO "LIGHT_CURTAIN", curtain_clear;
        AliasIO "DOOR_LOCK", door_lock;
        WHILE TRUE DO
            SetDO door_lock, 1;
            IF door_closed = 1 THEN
                MoveJ pick, v, zone, gripper;
                IF curtain_clear = 1 THEN
                    MoveL station, v, zone, gripper;
                ENDIF
                MoveJ home, v, zone, gripper;
            ENDIF
            ! Let the operator in between two cycles.
            SetDO door_lock, 0;
        ENDWHILE
    ENDPROC
ENDMODULE
