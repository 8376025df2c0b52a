MODULE seam_schedule
  ! A welding schedule in the style of the survey's arc-welding cell: the plate
  ! thickness and the station number live in a job module that is not given and
  ! are compared with numbers; a part sensor without a prefix is tested with = 1.
  PERS num nSchedule := 0;
  PERS bool bAlarm := FALSE;

  PROC main()
    WaitUntil partSensor = 1;
    IF nThickness <= 2.9 THEN
      nSchedule := 25;
    ELSEIF nThickness > 5.9 AND nThickness <= 6.9 THEN
      nSchedule := 60;
    ELSE
      bAlarm := TRUE;
    ENDIF
    TEST nStation
    CASE 1, 2:
      TPWrite "front";
    CASE 3:
      TPWrite "back";
    ENDTEST
  ENDPROC
ENDMODULE
